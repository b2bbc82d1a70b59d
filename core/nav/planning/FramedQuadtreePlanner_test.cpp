// Tests the framed-quadtree planner: on random grids its paths start and end exactly at the points
// given, every segment is free, and none is longer than grid A*'s octile path (nor is a path found
// where grid A* finds none); start and goal off the cell centres; its typed errors and config
// checks; and wall costs pull a path along a corridor wall towards the corridor's middle.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/testing/RandomGrids.h"
#include "core/nav/planning/FramedQuadtreePlanner.h"
#include "core/nav/planning/GridAStar.h"
#include "core/nav/planning/SegmentVisibility.h"

using Eigen::Vector2d;
using rgnav::Cell;
using rgnav::CellIndex;
using rgnav::CellUnitPath;
using rgnav::FramedQuadtreePlanner;
using rgnav::FramedQuadtreePlannerConfig;
using rgnav::OccupancyGrid;
using rgnav::testing::randomGrid;
using rgnav::testing::randomFreeCell;

namespace {

void checkPath(const OccupancyGrid& grid, const CellUnitPath& path, const Vector2d& start, const Vector2d& goal) {
  CPPUNIT_ASSERT(path.points.front() == start);
  CPPUNIT_ASSERT(path.points.back() == goal);
  double length = 0.0;
  for (std::size_t i = 1; i < path.points.size(); ++i) {
    CPPUNIT_ASSERT(rgnav::segmentFree(grid, path.points[i - 1], path.points[i]));
    length += (path.points[i] - path.points[i - 1]).norm();
  }
  CPPUNIT_ASSERT_DOUBLES_EQUAL(length, path.length, 1e-9);
  CPPUNIT_ASSERT(path.length >= (goal - start).norm() - 1e-9);
}

template <class E>
void checkThrowsNaming(const FramedQuadtreePlanner& planner, const Vector2d& start, const Vector2d& goal,
                       const std::string& named) {
  try {
    planner.plan(start, goal);
    CPPUNIT_FAIL("no error for " + named);
  } catch (const E& e) {
    CPPUNIT_ASSERT_MESSAGE(e.what(), std::string(e.what()).find(named) != std::string::npos);
  }
}

}  // namespace

class FramedQuadtreePlannerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(FramedQuadtreePlannerTest);
  CPPUNIT_TEST(pathsAreFreeAndNoLongerThanGridAStar);
  CPPUNIT_TEST(pointsOffTheCellCentres);
  CPPUNIT_TEST(aFreeGridGivesTheStraightLine);
  CPPUNIT_TEST(typedErrors);
  CPPUNIT_TEST(invalidConfigs);
  CPPUNIT_TEST(wallCostsKeepThePathAwayFromWalls);
  CPPUNIT_TEST_SUITE_END();

 public:
  void pathsAreFreeAndNoLongerThanGridAStar() {
    std::mt19937 rng(3);
    int compared = 0, unconnected = 0;
    for (int trial = 0; trial < 40; ++trial) {
      const OccupancyGrid grid = randomGrid(rng, 30 + trial, 50 - trial / 2, 0.05 + 0.01 * trial);
      const FramedQuadtreePlanner planner(grid);
      const rgnav::GridAStar baseline(grid);
      for (int k = 0; k < 20; ++k) {
        const CellIndex a = randomFreeCell(rng, grid), b = randomFreeCell(rng, grid);
        const Vector2d start(a.col + 0.5, a.row + 0.5), goal(b.col + 0.5, b.row + 0.5);
        double octile = 0.0;
        try {
          octile = baseline.plan(a, b).length;
        } catch (const rgnav::NoPathError&) {
          // The planner's collision model lets a diagonal touch one blocked corner, grid A* not;
          // so it may connect what grid A* cannot, never the reverse.
          ++unconnected;
          continue;
        }
        const CellUnitPath path = planner.plan(start, goal);
        checkPath(grid, path, start, goal);
        CPPUNIT_ASSERT(path.length <= octile + 1e-9);
        ++compared;
      }
    }
    CPPUNIT_ASSERT(compared > 400);
    CPPUNIT_ASSERT(unconnected > 10);
  }

  void pointsOffTheCellCentres() {
    std::mt19937 rng(5);
    const OccupancyGrid grid = randomGrid(rng, 40, 40, 0.15);
    const FramedQuadtreePlanner planner(grid);
    std::uniform_real_distribution<double> within(0.0, 1.0);
    int planned = 0;
    for (int k = 0; k < 200; ++k) {
      const CellIndex a = randomFreeCell(rng, grid), b = randomFreeCell(rng, grid);
      const Vector2d start(a.col + within(rng), a.row + within(rng));
      const Vector2d goal(b.col + (k % 2 ? 0.0 : within(rng)), b.row + (k % 3 ? 1.0 : within(rng)));
      try {
        checkPath(grid, planner.plan(start, goal), start, goal);
        ++planned;
      } catch (const rgnav::NoPathError&) {
      }
    }
    CPPUNIT_ASSERT(planned > 100);
  }

  void aFreeGridGivesTheStraightLine() {
    OccupancyGrid grid(50, 30, 0.05);
    const FramedQuadtreePlanner planner(grid);
    const CellUnitPath path = planner.plan({0.5, 0.5}, {49.5, 17.25});
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, path.points.size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(std::hypot(49.0, 16.75), path.length, 1e-12);
  }

  void typedErrors() {
    OccupancyGrid grid(9, 9, 0.05);
    for (int r = 0; r < 9; ++r) grid.set({4, r}, Cell::Occupied);
    const FramedQuadtreePlanner planner(grid);
    checkThrowsNaming<rgnav::StartBlockedError>(planner, {4.5, 2.5}, {0.5, 0.5}, "(4.5, 2.5)");
    checkThrowsNaming<rgnav::StartBlockedError>(planner, {-0.5, 2.5}, {0.5, 0.5}, "(-0.5, 2.5)");
    checkThrowsNaming<rgnav::StartBlockedError>(
        planner, {std::numeric_limits<double>::quiet_NaN(), 1.0}, {0.5, 0.5}, "nan");
    checkThrowsNaming<rgnav::GoalBlockedError>(planner, {0.5, 0.5}, {4.2, 8.9}, "(4.2, 8.9)");
    checkThrowsNaming<rgnav::GoalBlockedError>(planner, {0.5, 0.5}, {0.5, 9.5}, "(0.5, 9.5)");
    checkThrowsNaming<rgnav::NoPathError>(planner, {0.5, 0.5}, {8.5, 8.5}, "(8.5, 8.5)");
    // On the border of a free cell (the wall's side, the grid's edge) is inside.
    checkPath(grid, planner.plan({4.0, 3.0}, {0.0, 9.0}), {4.0, 3.0}, {0.0, 9.0});
  }

  void invalidConfigs() {
    const OccupancyGrid grid(4, 4, 0.05);
    CPPUNIT_ASSERT_THROW(FramedQuadtreePlanner(grid, {-0.1, 1.0}), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(FramedQuadtreePlanner(grid, {0.5, -1.0}), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(rgnav::validate({std::numeric_limits<double>::infinity(), 1.0}), rgnav::ConfigError);
    CPPUNIT_ASSERT_THROW(rgnav::validate({0.5, std::numeric_limits<double>::quiet_NaN()}), rgnav::ConfigError);
    rgnav::validate({0.0, 0.0});
  }

  // A corridor 11 cells (0.55 m) wide; from one end to the other along its lower wall. Without wall
  // costs the path runs along the wall; with them it moves towards the middle (0.25 m from the wall).
  void wallCostsKeepThePathAwayFromWalls() {
    OccupancyGrid grid(80, 13, 0.05, {}, Cell::Occupied);
    for (int r = 1; r <= 11; ++r)
      for (int c = 1; c < 79; ++c) grid.set({c, r}, Cell::Free);
    const Vector2d start(1.5, 1.5), goal(78.5, 1.5);
    const auto highest = [](const CellUnitPath& path) {
      double y = 0.0;
      for (const Vector2d& p : path.points) y = std::max(y, p.y());
      return y;
    };
    const CellUnitPath plain = FramedQuadtreePlanner(grid).plan(start, goal);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.5, highest(plain), 1e-12);
    const OccupancyGrid& g = grid;
    const CellUnitPath kept = FramedQuadtreePlanner(g, {0.3, 5.0}).plan(start, goal);
    checkPath(grid, kept, start, goal);
    CPPUNIT_ASSERT_MESSAGE(std::to_string(highest(kept)), highest(kept) >= 5.0);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(FramedQuadtreePlannerTest);
