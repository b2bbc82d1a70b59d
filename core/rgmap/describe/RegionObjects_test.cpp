// Tests detectRegionObjects (RegionObjects.h): a cabinet's sides give a rectangle with its pose
// and size; floor the freespace map holds as free (a room, a corridor) gives none, nor do a
// wall-thin block and a room seen from outside; a room-sized rectangle does not suppress the
// cabinet inside it.
#include "core/rgmap/describe/RegionObjects.h"

#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/lines/testing/SyntheticScan.h"

using Eigen::Vector2d;
using rgnav::FreespaceBitmap;
using rgnav::LineSegment;
using rgnav::Rectangle2D;

namespace {

// The four sides of an axis-aligned box, each 5 cm short of its corners.
std::vector<LineSegment> boxLines(const Vector2d& centre, double length, double width, std::uint64_t firstId) {
  std::vector<LineSegment> lines;
  const auto walls = rgnav::testing::boxWalls(centre, 0.0, length, width);
  for (std::size_t s = 0; s < walls.size(); ++s) {
    const Vector2d d = (walls[s].b - walls[s].a).normalized();
    lines.push_back(rgnav::segmentFromEndpoints(firstId + s, walls[s].a + 0.05 * d, walls[s].b - 0.05 * d));
  }
  return lines;
}

// A 15 cm freespace map of [0, 6) x [0, 6), free inside the axis-aligned box (lo, hi) except
// inside (holeLo, holeHi).
FreespaceBitmap floorMap(const Vector2d& lo, const Vector2d& hi, const Vector2d& holeLo, const Vector2d& holeHi) {
  FreespaceBitmap map = FreespaceBitmap::allOccupied(0.15, {0.0, 0.0}, 40, 40);
  const auto inside = [](const Vector2d& p, const Vector2d& a, const Vector2d& b) {
    return (p.array() > a.array()).all() && (p.array() < b.array()).all();
  };
  for (int row = 0; row < map.height; ++row)
    for (int col = 0; col < map.width; ++col) {
      const Vector2d c = map.cellCenter(col, row);
      if (inside(c, lo, hi) && !inside(c, holeLo, holeHi)) map.setFree(col, row);
    }
  return map;
}

}  // namespace

class RegionObjectsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RegionObjectsTest);
  CPPUNIT_TEST(cabinetInARoomIsTheOnlyObject);
  CPPUNIT_TEST(floorSeenFreeIsNoObject);
  CPPUNIT_TEST(wallThinBlockIsNoObject);
  CPPUNIT_TEST(roomSeenFromOutsideIsNoObject);
  CPPUNIT_TEST(invalidParametersAreRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void cabinetInARoomIsTheOnlyObject() {
    std::vector<LineSegment> lines = boxLines({3.0, 3.0}, 5.0, 4.0, 1);
    const std::vector<LineSegment> cabinet = boxLines({2.0, 2.5}, 1.2, 0.6, 10);
    lines.insert(lines.end(), cabinet.begin(), cabinet.end());
    const FreespaceBitmap map = floorMap({0.5, 1.0}, {5.5, 5.0}, {1.4, 2.2}, {2.6, 2.8});
    const std::vector<Rectangle2D> found = rgnav::detectRegionObjects(lines, map);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), found.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, found[0].pose.x, 0.05);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.5, found[0].pose.y, 0.05);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.2, found[0].lengthM, 0.05);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.6, found[0].widthM, 0.05);
    CPPUNIT_ASSERT(std::fabs(std::sin(found[0].pose.theta)) < 0.05);  // length along x
  }

  void floorSeenFreeIsNoObject() {
    const std::vector<LineSegment> lines = boxLines({2.0, 2.5}, 1.2, 0.6, 1);
    const FreespaceBitmap seenThrough = floorMap({0.5, 1.0}, {5.5, 5.0}, {0.0, 0.0}, {0.0, 0.0});
    CPPUNIT_ASSERT(rgnav::detectRegionObjects(lines, seenThrough).empty());
    const FreespaceBitmap unseen = FreespaceBitmap::allOccupied(0.15, {0.0, 0.0}, 40, 40);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), rgnav::detectRegionObjects(lines, unseen).size());
  }

  void wallThinBlockIsNoObject() {
    const FreespaceBitmap unseen = FreespaceBitmap::allOccupied(0.15, {0.0, 0.0}, 40, 40);
    CPPUNIT_ASSERT(rgnav::detectRegionObjects(boxLines({3.0, 3.0}, 4.4, 0.4, 1), unseen).empty());
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), rgnav::detectRegionObjects(boxLines({3.0, 3.0}, 3.6, 0.4, 1), unseen).size());
    CPPUNIT_ASSERT(rgnav::detectRegionObjects(boxLines({3.0, 3.0}, 1.5, 0.25, 1), unseen).empty());
  }

  void roomSeenFromOutsideIsNoObject() {
    const FreespaceBitmap unseen = FreespaceBitmap::allOccupied(0.15, {0.0, 0.0}, 40, 40);
    CPPUNIT_ASSERT(rgnav::detectRegionObjects(boxLines({3.0, 3.0}, 3.5, 2.5, 1), unseen).empty());
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), rgnav::detectRegionObjects(boxLines({3.0, 3.0}, 3.5, 1.8, 1), unseen).size());
  }

  void invalidParametersAreRefused() {
    rgnav::RegionObjectParams params;
    params.maxSeenFreeShare = 1.5;
    CPPUNIT_ASSERT_THROW(rgnav::detectRegionObjects({}, {}, params), rgnav::InvalidArgumentError);
    params = {};
    params.maxAspectRatio = 0.5;
    CPPUNIT_ASSERT_THROW(rgnav::detectRegionObjects({}, {}, params), rgnav::InvalidArgumentError);
    params = {};
    params.rectangles.maxOverlapRatio = 1.0;
    CPPUNIT_ASSERT_THROW(rgnav::detectRegionObjects({}, {}, params), rgnav::InvalidArgumentError);
    params = {};
    params.minWidthM = 3.0;
    CPPUNIT_ASSERT_THROW(rgnav::detectRegionObjects({}, {}, params), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RegionObjectsTest);
