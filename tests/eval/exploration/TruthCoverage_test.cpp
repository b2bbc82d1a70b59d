// Tests the truth an exploration is measured against (TruthCoverage.h) on a hand-made floor: the
// reachable area stops at a passage narrower than the robot, a scan of the true laser marks the
// cells in front of it (not behind: its heading counts) and no farther than the useful range, a
// cell seen twice counts once, and rooms count as reachable and found by the documented rules.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/sim/world/Raycaster.h"
#include "tests/eval/exploration/TruthCoverage.h"

using namespace rgnav;

namespace {

constexpr double kResolution = 0.05;
constexpr int kWidth = 120, kHeight = 60;  // 6 m x 3 m

// Room 0: columns 1..59; a wall at column 60 with a 1 m door (rows 20..39); room 1: columns
// 61..89; a wall at column 90 with a 0.2 m slit (rows 28..31); room 2: columns 91..118. Border walls.
OccupancyGrid floorPlan() {
  OccupancyGrid grid(kWidth, kHeight, kResolution);
  for (int row = 0; row < kHeight; ++row)
    for (int col = 0; col < kWidth; ++col) {
      const bool border = row == 0 || col == 0 || row == kHeight - 1 || col == kWidth - 1;
      const bool door = col == 60 && !(row >= 20 && row < 40);
      const bool slit = col == 90 && !(row >= 28 && row < 32);
      if (border || door || slit) grid.set({col, row}, Cell::Occupied);
    }
  return grid;
}

GroundTruth rooms(const OccupancyGrid& grid) {
  GroundTruth truth;
  truth.width = grid.width();
  truth.height = grid.height();
  truth.resolution = kResolution;
  truth.roomCount = 3;
  truth.labels.assign(grid.cells().size(), -1);
  for (int row = 1; row < kHeight - 1; ++row)
    for (int col = 1; col < kWidth - 1; ++col)
      truth.labels[std::size_t(row * kWidth + col)] = col < 60 ? 0 : col > 60 && col < 90 ? 1 : col > 90 ? 2 : -1;
  return truth;
}

std::size_t cellAt(double x, double y) { return std::size_t(int(y / kResolution) * kWidth + int(x / kResolution)); }

// A 180-degree scan of 1-degree beams from `sensor`, ranges cast in `grid` (30 m).
LaserScan scanFrom(const OccupancyGrid& grid, const Pose2D& sensor) {
  LaserScan scan;
  scan.sensorPose = sensor;
  scan.startAngle = -M_PI / 2.0;
  scan.angleIncrement = M_PI / 180.0;
  scan.maxRange = 30.0;
  scan.ranges.assign(181, 0.0f);
  Raycaster(grid).scan(sensor, scan.startAngle, scan.angleIncrement, scan.maxRange, scan.ranges);
  return scan;
}

}  // namespace

class TruthCoverageTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(TruthCoverageTest);
  CPPUNIT_TEST(reachableAreaStopsWhereTheRobotDoesNotPass);
  CPPUNIT_TEST(aScanSeesInFrontOfTheLaserWithinTheUsefulRange);
  CPPUNIT_TEST(roomsAreFoundWhenHalfOfThemWasSeen);
  CPPUNIT_TEST_SUITE_END();

 public:
  void reachableAreaStopsWhereTheRobotDoesNotPass() {
    const OccupancyGrid grid = floorPlan();
    const GroundTruth truth = rooms(grid);
    const TruthCoverage coverage(grid, truth, {0.5, 1.5}, 0.25, 8.0);
    CPPUNIT_ASSERT(coverage.reachable(cellAt(1.0, 1.0)));
    CPPUNIT_ASSERT(coverage.reachable(cellAt(0.1, 1.0)));   // along a wall: the robot's disk covers it
    CPPUNIT_ASSERT(!coverage.reachable(cellAt(0.1, 0.1)));  // a corner it does not
    CPPUNIT_ASSERT(coverage.reachable(cellAt(3.5, 1.5)));  // through the door
    CPPUNIT_ASSERT(!coverage.reachable(cellAt(5.0, 1.5)));  // behind the slit
    CPPUNIT_ASSERT(!coverage.reachable(cellAt(3.02, 0.5)));  // the wall
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), coverage.seenCells());
    const std::vector<RoomCoverage> byRoom = coverage.rooms();
    CPPUNIT_ASSERT(byRoom[0].reachable() && byRoom[1].reachable() && !byRoom[2].reachable());
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), byRoom[2].reachableCells);
    // The door's cells belong to no room.
    CPPUNIT_ASSERT_EQUAL(coverage.reachableCells(), byRoom[0].reachableCells + byRoom[1].reachableCells + 20);
  }

  void aScanSeesInFrontOfTheLaserWithinTheUsefulRange() {
    const OccupancyGrid grid = floorPlan();
    const GroundTruth truth = rooms(grid);
    TruthCoverage coverage(grid, truth, {0.5, 1.5}, 0.25, 2.0);
    const LaserScan scan = scanFrom(grid, {1.0, 1.5, 0.0});  // facing +x
    coverage.addScan(scan);
    CPPUNIT_ASSERT(coverage.seen(cellAt(2.5, 1.5)));
    CPPUNIT_ASSERT(coverage.seen(cellAt(1.0, 0.3)));   // the beam to the right, down to the wall
    CPPUNIT_ASSERT(!coverage.seen(cellAt(0.4, 1.5)));  // behind the laser
    CPPUNIT_ASSERT(!coverage.seen(cellAt(3.5, 1.5)));  // beyond the useful range
    const std::size_t once = coverage.seenCells();
    coverage.addScan(scan);
    CPPUNIT_ASSERT_EQUAL(once, coverage.seenCells());
    CPPUNIT_ASSERT(coverage.seenShare() > 0.0 && coverage.seenShare() < 1.0);
  }

  void roomsAreFoundWhenHalfOfThemWasSeen() {
    const OccupancyGrid grid = floorPlan();
    const GroundTruth truth = rooms(grid);
    TruthCoverage coverage(grid, truth, {0.5, 1.5}, 0.25, 8.0);
    coverage.addScan(scanFrom(grid, {0.3, 1.5, 0.0}));
    std::vector<RoomCoverage> byRoom = coverage.rooms();
    CPPUNIT_ASSERT(byRoom[0].found());
    CPPUNIT_ASSERT(!byRoom[1].found());
    coverage.addScan(scanFrom(grid, {3.2, 1.5, 0.0}));
    byRoom = coverage.rooms();
    CPPUNIT_ASSERT(byRoom[1].found());
    CPPUNIT_ASSERT(!byRoom[2].found());  // seen through the slit, but not reachable
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(TruthCoverageTest);
