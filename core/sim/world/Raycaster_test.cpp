// Tests the raycaster: ranges equal analytic distances in a box world with a pillar within one
// cell for many poses and angles (exactly, where walls lie on cell boundaries), hit points on
// the walls of a rotated rasterized room, leaps that never change a result compared with plain
// cell-by-cell traversal on a real floor plan, max range, the grid border and scans.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <limits>
#include <random>

#include "core/logs/LogTestFiles.h"
#include "core/sim/world/FloorPlan.h"
#include "core/sim/world/Raycaster.h"
#include "core/sim/world/VectorWorldRaster.h"

using namespace rgnav;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kRes = 0.05;

struct Rect {
  double x0, y0, x1, y1;
  bool contains(double x, double y) const { return x > x0 && x < x1 && y > y0 && y < y1; }
};

// Ray parameter at which o + t d leaves `r` (o inside r).
double exitDistance(const Rect& r, double ox, double oy, double dx, double dy) {
  const double tx = dx > 0 ? (r.x1 - ox) / dx : dx < 0 ? (r.x0 - ox) / dx : kInf;
  const double ty = dy > 0 ? (r.y1 - oy) / dy : dy < 0 ? (r.y0 - oy) / dy : kInf;
  return std::min(tx, ty);
}

// Ray parameter at which o + t d enters `r` (o outside r), or +inf.
double entryDistance(const Rect& r, double ox, double oy, double dx, double dy) {
  double lo = 0.0, hi = kInf;
  const double o[2] = {ox, oy}, d[2] = {dx, dy}, a[2] = {r.x0, r.y0}, b[2] = {r.x1, r.y1};
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (o[k] < a[k] || o[k] > b[k]) return kInf;
      continue;
    }
    const double t0 = (a[k] - o[k]) / d[k], t1 = (b[k] - o[k]) / d[k];
    lo = std::max(lo, std::min(t0, t1));
    hi = std::min(hi, std::max(t0, t1));
  }
  return lo <= hi ? lo : kInf;
}

// Room [-0.9, 6.9] x [-1.85, 2.85] with a pillar [2, 3] x [0, 0.5], walls on cell boundaries.
const Rect kRoom{-0.9, -1.85, 6.9, 2.85};
const Rect kPillar{2.0, 0.0, 3.0, 0.5};

OccupancyGrid boxWorld() {
  OccupancyGrid grid(160, 100, kRes, {-1.0, -2.0}, Cell::Occupied);
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const WorldPoint c = grid.center({col, row});
      if (kRoom.contains(c.x, c.y) && !kPillar.contains(c.x, c.y)) grid.set({col, row}, Cell::Free);
    }
  }
  return grid;
}

double analyticRange(double ox, double oy, double angle) {
  const double dx = std::cos(angle), dy = std::sin(angle);
  return std::min(exitDistance(kRoom, ox, oy, dx, dy), entryDistance(kPillar, ox, oy, dx, dy));
}

// Plain Amanatides-Woo traversal, cell by cell, as the reference for the leaping raycaster.
double referenceCast(const OccupancyGrid& grid, WorldPoint from, double angle, double maxRange) {
  const double x = (from.x - grid.origin().x) / grid.resolution(), y = (from.y - grid.origin().y) / grid.resolution();
  const double dx = std::cos(angle), dy = std::sin(angle), maxT = maxRange / grid.resolution();
  CellIndex c{int(std::floor(x)), int(std::floor(y))};
  if (grid.blocked(c)) return 0.0;
  const int sx = dx > 0 ? 1 : -1, sy = dy > 0 ? 1 : -1;
  double tx = dx > 0 ? (c.col + 1 - x) / dx : dx < 0 ? (c.col - x) / dx : kInf;
  double ty = dy > 0 ? (c.row + 1 - y) / dy : dy < 0 ? (c.row - y) / dy : kInf;
  for (;;) {
    double t;
    if (tx < ty) {
      t = tx;
      tx += std::abs(1.0 / dx);
      c.col += sx;
    } else {
      t = ty;
      ty += std::abs(1.0 / dy);
      c.row += sy;
    }
    if (t >= maxT) return kInf;
    if (grid.blocked(c)) return t * grid.resolution();
  }
}

}  // namespace

class RaycasterTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RaycasterTest);
  CPPUNIT_TEST(boxWorldRangesAreAnalytic);
  CPPUNIT_TEST(maxRangeGivesNoReturn);
  CPPUNIT_TEST(rotatedRoomHitsLieOnItsWalls);
  CPPUNIT_TEST(leapsMatchCellByCellTraversal);
  CPPUNIT_TEST(startInWallOutsideAndBorder);
  CPPUNIT_TEST(scanIsCastPerBeam);
  CPPUNIT_TEST_SUITE_END();

 public:
  void boxWorldRangesAreAnalytic() {
    const Raycaster raycaster(boxWorld());
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> x(kRoom.x0, kRoom.x1), y(kRoom.y0, kRoom.y1);
    int poses = 0;
    double worst = 0.0;
    while (poses < 60) {
      const double ox = x(rng), oy = y(rng);
      if (!kRoom.contains(ox, oy) || kPillar.contains(ox, oy)) continue;
      ++poses;
      for (int k = 0; k < 720; ++k) {
        const double angle = -M_PI + k * M_PI / 360.0;
        const double expected = analyticRange(ox, oy, angle);
        const double range = raycaster.cast({ox, oy}, angle, 30.0);
        worst = std::max(worst, std::abs(range - expected));
        CPPUNIT_ASSERT_DOUBLES_EQUAL(expected, range, kRes);
      }
    }
    // Walls on cell boundaries: the traversal is exact up to float rounding.
    CPPUNIT_ASSERT_MESSAGE(std::to_string(worst), worst < 1e-5);
  }

  void maxRangeGivesNoReturn() {
    const Raycaster raycaster(boxWorld());
    for (int k = 0; k < 360; ++k) {
      const double angle = k * M_PI / 180.0;
      const double expected = analyticRange(0.3, 0.2, angle);
      const float range = raycaster.cast({0.3, 0.2}, angle, 3.0);
      if (expected > 3.0 + 1e-6) {
        CPPUNIT_ASSERT(std::isinf(range) && range > 0);
      } else if (expected < 3.0 - 1e-6) {
        CPPUNIT_ASSERT_DOUBLES_EQUAL(expected, range, 1e-5);
      }
    }
  }

  // A 6 x 4 m room turned by 0.5 rad, drawn by the rasterizer: every hit point lies within one
  // cell diagonal of the room's inner wall faces.
  void rotatedRoomHitsLieOnItsWalls() {
    const double yaw = 0.5, c = std::cos(yaw), s = std::sin(yaw);
    const auto toWorld = [&](double u, double v) { return WorldPoint{5.0 + c * u - s * v, 5.0 + s * u + c * v}; };
    VectorWorld world;
    world.max = {10.0, 10.0};
    const double corners[4][2] = {{-3.1, -2.1}, {3.1, -2.1}, {3.1, 2.1}, {-3.1, 2.1}};  // wall centre lines
    for (int i = 0; i < 4; ++i) {
      const int j = (i + 1) % 4;
      world.walls.push_back({"", toWorld(corners[i][0], corners[i][1]), toWorld(corners[j][0], corners[j][1]), 0.2, 2.5});
    }
    const Raycaster raycaster(rasterize(world));
    const Rect inner{-3.0, -2.0, 3.0, 2.0};  // in the room's frame
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-2.7, 2.7), v(-1.7, 1.7);
    for (int pose = 0; pose < 40; ++pose) {
      const double pu = u(rng), pv = v(rng);
      const WorldPoint origin = toWorld(pu, pv);
      for (int k = 0; k < 360; ++k) {
        const double angle = k * M_PI / 180.0;
        const double range = raycaster.cast(origin, angle, 30.0);
        // The hit point in the room's frame, and its distance to the nearest inner face.
        const double hu = pu + range * std::cos(angle - yaw), hv = pv + range * std::sin(angle - yaw);
        const double du = std::max({inner.x0 - hu, hu - inner.x1, 0.0}), dv = std::max({inner.y0 - hv, hv - inner.y1, 0.0});
        const double offWall = inner.contains(hu, hv)
                                   ? std::min({hu - inner.x0, inner.x1 - hu, hv - inner.y0, inner.y1 - hv})
                                   : std::hypot(du, dv);
        CPPUNIT_ASSERT_MESSAGE(std::to_string(offWall), offWall <= std::sqrt(2.0) * kRes);
        const double analytic = exitDistance(inner, pu, pv, std::cos(angle - yaw), std::sin(angle - yaw));
        CPPUNIT_ASSERT(range <= analytic + 0.3);  // never through the 0.2 m wall
      }
    }
  }

  void leapsMatchCellByCellTraversal() {
    const OccupancyGrid grid = loadFloorPlan(
        rgnav::testing::sharedData("floorplans/ipa_room_segmentation/test_maps/lab_intel_furnitures.png"));
    const Raycaster raycaster(grid);
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<int> col(0, grid.width() - 1), row(0, grid.height() - 1);
    std::uniform_real_distribution<double> angle(-M_PI, M_PI), within(0.0, 1.0);
    const double axes[] = {0.0, M_PI / 2, M_PI, -M_PI / 2};
    int rays = 0;
    while (rays < 20000) {
      const CellIndex cell{col(rng), row(rng)};
      if (grid.at(cell) != Cell::Free) continue;
      // Every tenth ray starts on a cell corner, every tenth runs along an axis (not on a grid
      // line: a ray exactly on one touches the cells of both sides, and either may count).
      const WorldPoint corner{grid.origin().x + cell.col * kRes, grid.origin().y + cell.row * kRes};
      const WorldPoint from = rays % 10 == 0 ? corner
                                             : WorldPoint{corner.x + within(rng) * kRes, corner.y + within(rng) * kRes};
      const double a = rays % 10 == 5 ? axes[(rays / 10) % 4] : angle(rng);
      const double maxRange = rays % 3 == 0 ? 5.0 : 40.0;
      const double expected = referenceCast(grid, from, a, maxRange);
      const double range = raycaster.cast(from, a, maxRange);
      if (std::isinf(expected)) {
        CPPUNIT_ASSERT(std::isinf(range));
      } else {
        CPPUNIT_ASSERT_DOUBLES_EQUAL(expected, range, 1e-4);
      }
      ++rays;
    }
  }

  void startInWallOutsideAndBorder() {
    const Raycaster walls(boxWorld());
    CPPUNIT_ASSERT_EQUAL(0.0f, walls.cast({-0.95, 0.0}, 0.3, 10.0));  // inside the west wall
    CPPUNIT_ASSERT_EQUAL(0.0f, walls.cast({-5.0, 0.0}, 0.0, 10.0));   // outside the grid
    CPPUNIT_ASSERT_EQUAL(0.0f, walls.cast({1e300, std::nan("")}, 0.0, 10.0));
    CPPUNIT_ASSERT_THROW(walls.cast({0.0, 0.0}, std::nan(""), 10.0), InvalidArgumentError);
    // An empty grid: the border of the world stops every beam.
    const Raycaster open(OccupancyGrid(100, 50, kRes, {0.0, 0.0}));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.75, open.cast({1.25, 1.0}, 0.0, 30.0), 1e-5);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.5, open.cast({1.25, 1.0}, M_PI / 2, 30.0), 1e-5);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(std::hypot(1.25, 1.25), open.cast({1.25, 1.25}, -3 * M_PI / 4, 30.0), 1e-5);
    CPPUNIT_ASSERT(std::isinf(open.cast({1.25, 1.0}, 0.0, 2.0)));
  }

  void scanIsCastPerBeam() {
    const Raycaster raycaster(boxWorld());
    const Pose2D sensor{1.0, -0.5, 0.4};
    std::vector<float> ranges(361);
    raycaster.scan(sensor, -M_PI / 2, M_PI / 360, 30.0, ranges);
    for (std::size_t i = 0; i < ranges.size(); ++i) {
      CPPUNIT_ASSERT_EQUAL(raycaster.cast({1.0, -0.5}, 0.4 - M_PI / 2 + double(i) * M_PI / 360, 30.0), ranges[i]);
    }
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RaycasterTest);
