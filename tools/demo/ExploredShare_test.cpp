// Tests the explored share: on a small world of two rooms joined by a door, with a closed box of
// free cells (furniture's inside) that no path reaches, one region covering the first room gives
// that room's share of the reachable free cells (the box does not count), placed with the region's
// frame and mapToWorld; two regions covering both rooms give about 1 (the door's cells are in
// neither); a start on a wall gives 0.
#include "tools/demo/ExploredShare.h"

#include <cppunit/extensions/HelperMacros.h>

using namespace rgnav;

namespace {

constexpr double kRes = 0.05;

// 4 m x 2 m, walls around, a wall at x = 2 with a door at y 0.8..1.2, a closed 0.5 m box in room 2.
OccupancyGrid twoRooms() {
  OccupancyGrid grid(80, 40, kRes);
  for (int col = 0; col < 80; ++col)
    for (int row = 0; row < 40; ++row) {
      const bool outer = col == 0 || row == 0 || col == 79 || row == 39;
      const bool middle = col == 40 && !(row >= 16 && row < 24);
      const bool box = col >= 60 && col <= 70 && row >= 10 && row <= 20 && (col == 60 || col == 70 || row == 10 || row == 20);
      if (outer || middle || box) grid.set({col, row}, Cell::Occupied);
    }
  return grid;
}

// A region whose freespace covers [0, width] x [0, height] of its frame in 0.15 m cells.
RegionView region(const Pose2D& frame, double width, double height) {
  RegionView r;
  r.summary.frame = frame;
  r.freespace = FreespaceBitmap::allOccupied(0.15, {0.0, 0.0}, int(std::ceil(width / 0.15)), int(std::ceil(height / 0.15)));
  for (int c = 0; c < r.freespace.width; ++c)
    for (int row = 0; row < r.freespace.height; ++row) r.freespace.setFree(c, row);
  return r;
}

}  // namespace

class ExploredShareTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ExploredShareTest);
  CPPUNIT_TEST(shareOfTheReachableFreeCells);
  CPPUNIT_TEST_SUITE_END();

 public:
  void shareOfTheReachableFreeCells() {
    const OccupancyGrid world = twoRooms();
    // The map frame lies 1 m east of the world's. Room 1: columns 1..39, rows 1..38 (world x
    // 0.05..2.0 = map x -0.95..1.0); room 2: columns 41..78 without the box's 11 x 11 cells; the
    // door: 8 cells of column 40.
    const Pose2D mapToWorld{1.0, 0.0, 0.0};
    const double room1 = 39.0 * 38.0, room2 = 38.0 * 38.0 - 121.0, door = 8.0;
    const std::vector<RegionView> first{region({-0.95, 0.05, 0.0}, 1.95, 1.95)};
    CPPUNIT_ASSERT_DOUBLES_EQUAL(room1 / (room1 + room2 + door), exploredShare(world, {0.5, 1.0}, first, mapToWorld),
                                 1e-9);
    const std::vector<RegionView> both{first[0], region({1.05, 0.05, 0.0}, 1.95, 1.95)};
    CPPUNIT_ASSERT_DOUBLES_EQUAL((room1 + room2) / (room1 + room2 + door),
                                 exploredShare(world, {0.5, 1.0}, both, mapToWorld), 1e-9);
    CPPUNIT_ASSERT_EQUAL(0.0, exploredShare(world, {0.0, 0.0}, both, mapToWorld));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ExploredShareTest);
