// Tests the grid planner: the clearance map against brute force, paths through a door that keep
// away from walls, waypoints the robot fits along, and the typed refusals (start or goal blocked,
// door too narrow for the robot).
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/nav/grid/ClearanceMap.h"
#include "core/nav/grid/DiskFootprint.h"
#include "core/nav/grid/GridPlanner.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/sim/scenarios/GridDrawing.h"

using rgnav::Cell;
using rgnav::GridPlanner;
using rgnav::OccupancyGrid;
using rgnav::WorldPoint;

namespace {

// Two 4 x 4 m rooms side by side (x 0..4 and 4.1..8.1, y 0..4 inside 0.1 m walls), joined by a
// door of `doorWidth` centred at y = 2 in the 0.1 m wall between them.
OccupancyGrid twoRooms(double doorWidth) {
  OccupancyGrid grid(164, 84, 0.05, {-0.1, -0.1}, Cell::Occupied);
  rgnav::fillRect(grid, {0.0, 0.0, 3.99, 3.99}, Cell::Free);
  rgnav::fillRect(grid, {4.1, 0.0, 8.09, 3.99}, Cell::Free);
  rgnav::fillRect(grid, {3.95, 2.0 - doorWidth / 2.0, 4.15, 2.0 + doorWidth / 2.0}, Cell::Free);
  return grid;
}

// Every point along the waypoint polyline (every 1 cm) leaves room for the robot's disk.
void assertRobotFitsAlong(const OccupancyGrid& grid, const std::vector<WorldPoint>& path, double radius) {
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double length = std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
    const int n = std::max(1, static_cast<int>(length / 0.01));
    for (int k = 0; k <= n; ++k) {
      const double t = double(k) / n;
      const WorldPoint p{path[i - 1].x + t * (path[i].x - path[i - 1].x),
                         path[i - 1].y + t * (path[i].y - path[i - 1].y)};
      CPPUNIT_ASSERT(!rgnav::diskCollides(grid, p, radius));
    }
  }
}

}  // namespace

class GridPlannerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GridPlannerTest);
  CPPUNIT_TEST(clearanceMatchesBruteForce);
  CPPUNIT_TEST(findsPathThroughDoor);
  CPPUNIT_TEST(pathKeepsAwayFromWalls);
  CPPUNIT_TEST(refusesDoorTooNarrowForRobot);
  CPPUNIT_TEST(blockedStartAndGoalAreTypedErrors);
  CPPUNIT_TEST(reachabilityFollowsInflation);
  CPPUNIT_TEST_SUITE_END();

 public:
  void clearanceMatchesBruteForce() {
    OccupancyGrid grid(37, 23, 0.1, {1.0, -2.0});
    std::mt19937_64 rng(5);
    std::bernoulli_distribution occupied(0.03);
    for (int row = 0; row < grid.height(); ++row)
      for (int col = 0; col < grid.width(); ++col)
        if (occupied(rng)) grid.set({col, row}, Cell::Occupied);
    const rgnav::ClearanceMap map(grid);
    for (int row = 0; row < grid.height(); ++row) {
      for (int col = 0; col < grid.width(); ++col) {
        // Nearest blocked cell, including the ring just outside the grid.
        double best = std::numeric_limits<double>::infinity();
        for (int r = -1; r <= grid.height(); ++r)
          for (int c = -1; c <= grid.width(); ++c)
            if (grid.blocked({c, r})) best = std::min(best, std::hypot(double(c - col), double(r - row)));
        CPPUNIT_ASSERT_DOUBLES_EQUAL(best * 0.1, map.at({col, row}), 1e-5);
      }
    }
  }

  void findsPathThroughDoor() {
    const OccupancyGrid grid = twoRooms(0.9);
    const GridPlanner planner(grid);
    const std::vector<WorldPoint> path = planner.plan({0.8, 0.7}, {7.3, 3.2});
    CPPUNIT_ASSERT(path.size() >= 3);  // it has to bend through the door
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.8, path.front().x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.2, path.back().y, 1e-12);
    assertRobotFitsAlong(grid, path, 0.25);
    // The path crosses the wall between the rooms inside the door.
    bool crossed = false;
    for (std::size_t i = 1; i < path.size(); ++i) {
      if ((path[i - 1].x - 4.05) * (path[i].x - 4.05) <= 0.0) {
        const double t = (4.05 - path[i - 1].x) / (path[i].x - path[i - 1].x);
        const double y = path[i - 1].y + t * (path[i].y - path[i - 1].y);
        CPPUNIT_ASSERT(std::abs(y - 2.0) < 0.45 - 0.25);
        crossed = true;
      }
    }
    CPPUNIT_ASSERT(crossed);
  }

  // In an open room the cost keeps the path off the walls: a path along a wall moves inwards.
  void pathKeepsAwayFromWalls() {
    OccupancyGrid grid(200, 80, 0.05, {0.0, 0.0}, Cell::Occupied);
    rgnav::fillRect(grid, {0.1, 0.1, 9.9, 3.9}, Cell::Free);  // 9.8 x 3.8 m room
    const GridPlanner planner(grid);
    const std::vector<WorldPoint> path = planner.plan({0.5, 0.5}, {9.5, 0.5});
    double farthest = 0.0;
    for (const WorldPoint& p : path) farthest = std::max(farthest, p.y);
    CPPUNIT_ASSERT(farthest >= 0.8);  // moves out to the comfort clearance
    assertRobotFitsAlong(grid, path, 0.25);
    // Without the clearance cost it hugs the wall.
    rgnav::GridPlannerConfig plain;
    plain.clearanceWeight = 0.0;
    const std::vector<WorldPoint> straight = GridPlanner(grid, plain).plan({0.5, 0.5}, {9.5, 0.5});
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, straight.size());
  }

  void refusesDoorTooNarrowForRobot() {
    const OccupancyGrid grid = twoRooms(0.4);  // a 0.5 m robot does not fit
    const GridPlanner planner(grid);
    CPPUNIT_ASSERT_THROW(planner.plan({1.0, 2.0}, {7.0, 2.0}), rgnav::NoPathError);
    rgnav::GridPlannerConfig small;
    small.robotRadius = 0.15;
    CPPUNIT_ASSERT_NO_THROW(GridPlanner(grid, small).plan({1.0, 2.0}, {7.0, 2.0}));
  }

  void blockedStartAndGoalAreTypedErrors() {
    const OccupancyGrid grid = twoRooms(0.9);
    const GridPlanner planner(grid);
    CPPUNIT_ASSERT_THROW(planner.plan({0.1, 2.0}, {2.0, 2.0}), rgnav::StartBlockedError);  // at a wall
    CPPUNIT_ASSERT_THROW(planner.plan({-5.0, 2.0}, {2.0, 2.0}), rgnav::StartBlockedError);  // off the map
    CPPUNIT_ASSERT_THROW(planner.plan({2.0, 2.0}, {4.05, 0.5}), rgnav::GoalBlockedError);   // in the wall
    CPPUNIT_ASSERT_THROW(planner.plan({2.0, 2.0}, {20.0, 2.0}), rgnav::GoalBlockedError);
    rgnav::GridPlannerConfig bad;
    bad.robotRadius = -1.0;
    CPPUNIT_ASSERT_THROW(GridPlanner(grid, bad), rgnav::ConfigError);
  }

  void reachabilityFollowsInflation() {
    const OccupancyGrid grid = twoRooms(0.4);
    const GridPlanner planner(grid);
    const std::vector<bool> reachable = planner.reachableFrom({1.0, 2.0});
    const auto at = [&](WorldPoint p) {
      const rgnav::CellIndex c = *grid.cellOf(p);
      return reachable[static_cast<std::size_t>(c.row * grid.width() + c.col)];
    };
    CPPUNIT_ASSERT(at({3.0, 3.0}));
    CPPUNIT_ASSERT(planner.traversable(*grid.cellOf({6.0, 2.0})));  // free, just not connected
    CPPUNIT_ASSERT(!at({0.1, 3.0}));  // within the robot radius of the wall
    CPPUNIT_ASSERT(!at({6.0, 2.0}));  // behind the narrow door
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(GridPlannerTest);
