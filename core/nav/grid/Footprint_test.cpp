// Tests the robot footprints: sizes, rectangle corners, and the exact overlap tests of disks and
// rectangles (with a centre offset, rotated) against disks and grid cells, touching not counting.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <random>

#include "core/common/Errors.h"
#include "core/nav/grid/DiskFootprint.h"
#include "core/nav/grid/Footprint.h"

using rgnav::Cell;
using rgnav::Footprint;
using rgnav::OccupancyGrid;
using rgnav::Pose2D;
using rgnav::WorldPoint;

namespace {

// A free 2 x 2 m grid of 1/16 m cells (binary fractions keep the touching cases exact), origin
// (0, 0), with one occupied cell (col 16, row 16), which covers [1, 1.0625] x [1, 1.0625].
OccupancyGrid oneBlockedCell() {
  OccupancyGrid grid(32, 32, 0.0625, {0.0, 0.0});
  grid.set({16, 16}, Cell::Occupied);
  return grid;
}

// Whether a point lies strictly inside the rectangle footprint at `pose`, grown by `margin`.
bool insideRectangle(const Footprint& f, const Pose2D& pose, WorldPoint p, double margin) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double dx = p.x - pose.x, dy = p.y - pose.y;
  const double u = c * dx + s * dy - f.centerOffset, n = -s * dx + c * dy;
  return std::abs(u) < f.length / 2.0 + margin && std::abs(n) < f.width / 2.0 + margin;
}

// Whether any point of a 1 mm lattice over the grid lies in a blocked cell and inside the
// rectangle grown by `margin`.
bool sampledOverlap(const OccupancyGrid& grid, const Footprint& f, const Pose2D& pose, double margin) {
  for (double x = 0.0005; x < 2.0; x += 0.001) {
    for (double y = 0.0005; y < 2.0; y += 0.001) {
      if (!insideRectangle(f, pose, {x, y}, margin)) continue;
      if (grid.blocked(*grid.cellOf({x, y}))) return true;
    }
  }
  return false;
}

}  // namespace

class FootprintTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(FootprintTest);
  CPPUNIT_TEST(sizes);
  CPPUNIT_TEST(cornersFollowThePose);
  CPPUNIT_TEST(rectangleVersusDiskIsExact);
  CPPUNIT_TEST(diskVersusDiskIsExact);
  CPPUNIT_TEST(rectangleVersusCellIsExact);
  CPPUNIT_TEST(rotatedRectangleMissesTheCellInItsBoundingBox);
  CPPUNIT_TEST(rectangleAgreesWithSampling);
  CPPUNIT_TEST(diskVersusGridIsTheDiskTest);
  CPPUNIT_TEST(badSizesAreConfigErrors);
  CPPUNIT_TEST(nearestPointIsOnTheOutline);
  CPPUNIT_TEST_SUITE_END();

 public:
  void sizes() {
    const Footprint disk = Footprint::disk(0.3);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.3, disk.circumradius(), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.3, disk.inscribedRadius(), 1e-12);
    const Footprint jackal = Footprint::rectangle(0.508, 0.430);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(std::hypot(0.254, 0.215), jackal.circumradius(), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.215, jackal.inscribedRadius(), 1e-12);
    const Footprint ahead = Footprint::rectangle(0.6, 0.5, 0.2);  // from -0.1 to 0.5 along x
    CPPUNIT_ASSERT_DOUBLES_EQUAL(std::hypot(0.5, 0.25), ahead.circumradius(), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.1, ahead.inscribedRadius(), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, Footprint::rectangle(0.6, 0.5, 0.4).inscribedRadius(), 1e-12);
  }

  void nearestPointIsOnTheOutline() {
    const WorldPoint onDisk = Footprint::disk(0.25).nearestPoint({1.0, 1.0, 0.0}, {1.0, 2.0});
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, onDisk.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.25, onDisk.y, 1e-12);
    // Heading +y, x from 0.8 to 1.2, y from 1.8 to 2.4: off the front-left corner, then beside.
    const Footprint f = Footprint::rectangle(0.6, 0.4, 0.1);
    const WorldPoint corner = f.nearestPoint({1.0, 2.0, M_PI / 2.0}, {0.5, 3.0});
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.8, corner.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.4, corner.y, 1e-12);
    const WorldPoint side = f.nearestPoint({1.0, 2.0, M_PI / 2.0}, {2.0, 2.0});
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.2, side.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, side.y, 1e-12);
    const WorldPoint inside = f.nearestPoint({1.0, 2.0, M_PI / 2.0}, {1.1, 2.1});
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.1, inside.x, 1e-12);
  }

  void cornersFollowThePose() {
    CPPUNIT_ASSERT(Footprint::disk(0.2).corners({1.0, 2.0, 0.3}).empty());
    const Footprint f = Footprint::rectangle(0.6, 0.4, 0.1);
    // Heading +y: the rectangle spans y from 2 - 0.2 to 2 + 0.4 and x from 0.8 to 1.2.
    const auto c = f.corners({1.0, 2.0, M_PI / 2.0});
    CPPUNIT_ASSERT_EQUAL(std::size_t{4}, c.size());
    const WorldPoint expected[4] = {{1.2, 2.4}, {0.8, 2.4}, {0.8, 1.8}, {1.2, 1.8}};
    for (int i = 0; i < 4; ++i) {
      CPPUNIT_ASSERT_DOUBLES_EQUAL(expected[i].x, c[i].x, 1e-12);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(expected[i].y, c[i].y, 1e-12);
    }
  }

  void rectangleVersusDiskIsExact() {
    // x from -0.125 to 0.375, y from -0.25 to 0.25 (binary fractions: touching is exact).
    const Footprint f = Footprint::rectangle(0.5, 0.5, 0.125);
    const Pose2D at{0.0, 0.0, 0.0};
    // Ahead of the front edge: touching at r = 0.125.
    CPPUNIT_ASSERT(!f.overlapsDisk(at, {0.5, 0.0}, 0.125));
    CPPUNIT_ASSERT(f.overlapsDisk(at, {0.5, 0.0}, 0.125 + 1e-9));
    // Behind the rear edge (the offset moves it to -0.125).
    CPPUNIT_ASSERT(!f.overlapsDisk(at, {-0.25, 0.0}, 0.125));
    CPPUNIT_ASSERT(f.overlapsDisk(at, {-0.25, 0.0}, 0.125 + 1e-9));
    // Off the front-left corner (0.375, 0.25) by (0.1875, 0.25): 0.3125 away.
    CPPUNIT_ASSERT(!f.overlapsDisk(at, {0.5625, 0.5}, 0.3125));
    CPPUNIT_ASSERT(f.overlapsDisk(at, {0.5625, 0.5}, 0.3125 + 1e-9));
    // A point strictly inside overlaps; rotated by 90 degrees the front edge is at y = 1.375.
    CPPUNIT_ASSERT(f.overlapsDisk(at, {0.3, 0.1}, 0.0));
    const Pose2D up{1.0, 1.0, M_PI / 2.0};
    CPPUNIT_ASSERT(!f.overlapsDisk(up, {1.0, 1.5}, 0.125 - 1e-9));
    CPPUNIT_ASSERT(f.overlapsDisk(up, {1.0, 1.5}, 0.125 + 1e-9));
    CPPUNIT_ASSERT(!f.overlapsDisk(up, {1.5, 1.0}, 0.25 - 1e-9));
    CPPUNIT_ASSERT(f.overlapsDisk(up, {1.5, 1.0}, 0.25 + 1e-9));
  }

  void diskVersusDiskIsExact() {
    const Footprint f = Footprint::disk(0.25);
    CPPUNIT_ASSERT(!f.overlapsDisk({0.0, 0.0, 1.0}, {0.3, 0.4}, 0.25));
    CPPUNIT_ASSERT(f.overlapsDisk({0.0, 0.0, 1.0}, {0.3, 0.4}, 0.25 + 1e-9));
  }

  void rectangleVersusCellIsExact() {
    const OccupancyGrid grid = oneBlockedCell();
    const Footprint f = Footprint::rectangle(0.5, 0.25);
    // Front edge on the cell's left side x = 1: touching.
    CPPUNIT_ASSERT(!f.overlapsGrid(grid, {0.75, 1.03125, 0.0}));
    CPPUNIT_ASSERT(f.overlapsGrid(grid, {0.75 + 1e-9, 1.03125, 0.0}));
    // Left edge on the cell's bottom y = 1, heading along x.
    CPPUNIT_ASSERT(!f.overlapsGrid(grid, {1.03125, 0.875, 0.0}));
    CPPUNIT_ASSERT(f.overlapsGrid(grid, {1.03125, 0.875 + 1e-9, 0.0}));
    // Heading +y, the front edge below the cell, then into it.
    CPPUNIT_ASSERT(!f.overlapsGrid(grid, {1.03125, 0.75 - 1e-9, M_PI / 2.0}));
    CPPUNIT_ASSERT(f.overlapsGrid(grid, {1.03125, 0.75 + 1e-9, M_PI / 2.0}));
    // A rectangle far from the grid's edge sees none; one reaching outside the grid does.
    CPPUNIT_ASSERT(!f.overlapsGrid(grid, {0.5, 0.5, 0.3}));
    CPPUNIT_ASSERT(f.overlapsGrid(grid, {0.15, 0.5, 0.0}));
  }

  void rotatedRectangleMissesTheCellInItsBoundingBox() {
    const OccupancyGrid grid = oneBlockedCell();
    // A thin rectangle along the diagonal direction (1, -1) whose bounding box covers the cell
    // but whose centre line passes 0.05 m below-left of its corner (1.0, 1.0): its edge is 0.04 m
    // away, then touching, then overlapping.
    const Footprint f = Footprint::rectangle(0.6, 0.02);
    const auto beside = [](double gap) {
      const double d = gap / std::sqrt(2.0);
      return Pose2D{1.0 - d, 1.0 - d, -M_PI / 4.0};
    };
    CPPUNIT_ASSERT(!f.overlapsGrid(grid, beside(0.05)));
    CPPUNIT_ASSERT(!f.overlapsGrid(grid, beside(0.01 + 1e-9)));
    CPPUNIT_ASSERT(f.overlapsGrid(grid, beside(0.01 - 1e-9)));
  }

  void rectangleAgreesWithSampling() {
    const OccupancyGrid grid = oneBlockedCell();
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> pos(0.75, 1.3), angle(-M_PI, M_PI);
    const Footprint f = Footprint::rectangle(0.3, 0.12, 0.05);
    int overlaps = 0, misses = 0;
    for (int k = 0; k < 60; ++k) {
      const Pose2D pose{pos(rng), pos(rng), angle(rng)};
      const bool exact = f.overlapsGrid(grid, pose);
      // A sample inside both proves an overlap; an overlap leaves samples in the body grown by 1 mm.
      if (sampledOverlap(grid, f, pose, -0.001)) CPPUNIT_ASSERT(exact);
      if (exact) CPPUNIT_ASSERT(sampledOverlap(grid, f, pose, 0.001));
      (exact ? overlaps : misses) += 1;
    }
    CPPUNIT_ASSERT(overlaps > 5 && misses > 5);
  }

  void diskVersusGridIsTheDiskTest() {
    const OccupancyGrid grid = oneBlockedCell();
    const Footprint f = Footprint::disk(0.25);
    for (double x = 0.7; x < 1.4; x += 0.013) {
      CPPUNIT_ASSERT_EQUAL(rgnav::diskCollides(grid, {x, 1.1}, 0.25), f.overlapsGrid(grid, {x, 1.1, 0.7}));
    }
    CPPUNIT_ASSERT(!f.overlapsGrid(grid, {0.75, 1.03125, 0.0}));
    CPPUNIT_ASSERT(f.overlapsGrid(grid, {0.75 + 1e-9, 1.03125, 0.0}));
  }

  void badSizesAreConfigErrors() {
    CPPUNIT_ASSERT_NO_THROW(validate(Footprint::disk(0.25)));
    CPPUNIT_ASSERT_NO_THROW(validate(Footprint::rectangle(0.508, 0.43, -0.1)));
    CPPUNIT_ASSERT_THROW(validate(Footprint::disk(0.0)), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(validate(Footprint::disk(NAN)), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(validate(Footprint::rectangle(0.0, 0.4)), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(validate(Footprint::rectangle(0.5, -0.4)), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(validate(Footprint::rectangle(0.5, 0.4, INFINITY)), rgnav::ConfigError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(FootprintTest);
