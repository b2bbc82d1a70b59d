// Tests the laser obstacle grid: hits become obstacles, a moving person's trail is cleared by the
// beams that later pass through it while a wall stays, a person stepping into free space is a
// moving obstacle and the wall is not (until the person stood for the memory), and scrolling keeps
// what was seen.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <functional>

#include "core/nav/avoidance/LaserObstacleMap.h"

using rgnav::Cell;
using rgnav::LaserObstacleMap;
using rgnav::LaserScan;
using rgnav::ObstacleGrid;
using rgnav::Pose2D;

namespace {

// A 270 degree scan from `pose` whose beam at world angle a returns range(a).
LaserScan scanAt(const Pose2D& pose, double stamp, const std::function<float(double)>& range) {
  LaserScan scan;
  scan.stamp = stamp;
  scan.odometry = pose;
  scan.startAngle = -0.75 * M_PI;
  scan.angleIncrement = M_PI / 360.0;
  scan.maxRange = 30.0;
  for (int i = 0; i <= 540; ++i) scan.ranges.push_back(range(pose.theta + scan.startAngle + i * scan.angleIncrement));
  return scan;
}

// A wall along y = wallY seen from (x0, 0); beams not toward it return nothing.
float wallRange(double angle, double wallY) {
  const double s = std::sin(angle);
  return s > 0.05 ? static_cast<float>(wallY / s) : LaserScan::kNoReturn;
}

Cell cellAt(const ObstacleGrid& grid, double x, double y) { return grid.cells.at(*grid.cells.cellOf({x, y})); }

}  // namespace

class LaserObstacleMapTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LaserObstacleMapTest);
  CPPUNIT_TEST(hitsAreObstaclesAndBeamsClear);
  CPPUNIT_TEST(aPersonsTrailIsCleared);
  CPPUNIT_TEST(aPersonSteppingIntoFreeSpaceMoves);
  CPPUNIT_TEST(scrollingKeepsWhatWasSeen);
  CPPUNIT_TEST_SUITE_END();

 public:
  void hitsAreObstaclesAndBeamsClear() {
    LaserObstacleMap map({});
    map.add(scanAt({0, 0, M_PI / 2}, 1.0, [](double a) { return wallRange(a, 3.0); }));
    const ObstacleGrid grid = map.grid();
    CPPUNIT_ASSERT_EQUAL(std::string("laser"), grid.source);
    CPPUNIT_ASSERT_EQUAL(1.0, grid.stamp);
    CPPUNIT_ASSERT(cellAt(grid, 0.01, 3.01) == Cell::Occupied);
    CPPUNIT_ASSERT(cellAt(grid, 0.01, 1.5) == Cell::Free);
    CPPUNIT_ASSERT(cellAt(grid, 0.01, 4.5) == Cell::Unknown);  // behind the wall
    CPPUNIT_ASSERT(cellAt(grid, 0.01, -1.5) == Cell::Unknown);  // behind the laser's 270 degrees
  }

  void aPersonsTrailIsCleared() {
    LaserObstacleMap map({});
    // A person 0.5 m wide 2 m ahead in front of a wall at 5 m, then gone.
    const auto withPerson = [](double a) {
      return std::abs(a - M_PI / 2) < 0.12 ? 2.0f : wallRange(a, 5.0);
    };
    for (int i = 0; i < 5; ++i) map.add(scanAt({0, 0, M_PI / 2}, i * 0.1, withPerson));
    CPPUNIT_ASSERT(cellAt(map.grid(), 0.01, 2.01) == Cell::Occupied);
    for (int i = 5; i < 12; ++i) map.add(scanAt({0, 0, M_PI / 2}, i * 0.1, [](double a) { return wallRange(a, 5.0); }));
    const ObstacleGrid grid = map.grid();
    CPPUNIT_ASSERT(cellAt(grid, 0.01, 2.01) == Cell::Free);
    CPPUNIT_ASSERT(cellAt(grid, 0.01, 5.01) == Cell::Occupied);
  }

  void aPersonSteppingIntoFreeSpaceMoves() {
    LaserObstacleMap map({});
    const auto wall = [](double a) { return wallRange(a, 5.0); };
    const auto withPerson = [](double a) { return std::abs(a - M_PI / 2) < 0.12 ? 2.0f : wallRange(a, 5.0); };
    for (int i = 0; i < 5; ++i) map.add(scanAt({0, 0, M_PI / 2}, i * 0.1, wall));
    for (int i = 5; i < 8; ++i) map.add(scanAt({0, 0, M_PI / 2}, i * 0.1, withPerson));
    const ObstacleGrid grid = map.grid();
    const auto moving = [](const ObstacleGrid& g, double x, double y) { return g.moving.at(*g.moving.cellOf({x, y})); };
    CPPUNIT_ASSERT(cellAt(grid, 0.01, 2.01) == Cell::Occupied);
    CPPUNIT_ASSERT(moving(grid, 0.01, 2.01) == Cell::Occupied);
    CPPUNIT_ASSERT(cellAt(grid, 0.01, 5.01) == Cell::Occupied);
    CPPUNIT_ASSERT(moving(grid, 0.01, 5.01) == Cell::Free);
    // Standing there for longer than the memory (2 s): an obstacle like any other.
    for (int i = 8; i < 40; ++i) map.add(scanAt({0, 0, M_PI / 2}, i * 0.1, withPerson));
    CPPUNIT_ASSERT(moving(map.grid(), 0.01, 2.01) == Cell::Free);
    CPPUNIT_ASSERT(cellAt(map.grid(), 0.01, 2.01) == Cell::Occupied);
  }

  void scrollingKeepsWhatWasSeen() {
    rgnav::LaserObstacleMapConfig config;
    config.sizeM = 10.0;
    config.recenterMarginM = 3.0;
    LaserObstacleMap map(config);
    map.add(scanAt({0, 0, M_PI / 2}, 0.0, [](double a) { return wallRange(a, 1.0); }));
    // Far enough to scroll, looking away; this scan sees nothing.
    map.add(scanAt({0, -3.5, -M_PI / 2}, 0.1, [](double) { return LaserScan::kNoReturn; }));
    const ObstacleGrid grid = map.grid();
    CPPUNIT_ASSERT(grid.cells.origin().y < -5.0);
    CPPUNIT_ASSERT(cellAt(grid, 0.01, 1.01) == Cell::Occupied);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(LaserObstacleMapTest);
