// Tests the grid A* baseline: octile lengths on a free grid, the MovingAI rule (no diagonal step
// past a blocked cardinal cell), paths of 8-connected free steps, and its typed errors.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <cstdlib>

#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/GridAStar.h"

using rgnav::Cell;
using rgnav::CellIndex;
using rgnav::GridAStar;
using rgnav::OccupancyGrid;

class GridAStarTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GridAStarTest);
  CPPUNIT_TEST(freeGridGivesTheOctileDistance);
  CPPUNIT_TEST(diagonalStepsNeedBothCardinalCellsFree);
  CPPUNIT_TEST(typedErrors);
  CPPUNIT_TEST_SUITE_END();

 public:
  void freeGridGivesTheOctileDistance() {
    const OccupancyGrid grid(20, 12, 0.05);
    const GridAStar planner(grid);
    const rgnav::GridPath path = planner.plan({1, 2}, {15, 9});
    CPPUNIT_ASSERT_DOUBLES_EQUAL(7.0 + 7.0 * std::sqrt(2.0), path.length, 1e-12);
    CPPUNIT_ASSERT(path.cells.front() == (CellIndex{1, 2}));
    CPPUNIT_ASSERT(path.cells.back() == (CellIndex{15, 9}));
    for (std::size_t i = 1; i < path.cells.size(); ++i)
      CPPUNIT_ASSERT(std::max(std::abs(path.cells[i].col - path.cells[i - 1].col),
                              std::abs(path.cells[i].row - path.cells[i - 1].row)) == 1);
  }

  void diagonalStepsNeedBothCardinalCellsFree() {
    OccupancyGrid grid(3, 3, 0.05);
    grid.set({1, 0}, Cell::Occupied);
    const GridAStar planner(grid);
    // (0,0) -> (1,1) may not cut the corner of (1,0): up, then right.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, planner.plan({0, 0}, {1, 1}).length, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.0, planner.plan({0, 0}, {2, 1}).length, 1e-12);
  }

  void typedErrors() {
    OccupancyGrid grid(5, 5, 0.05);
    for (int r = 0; r < 5; ++r) grid.set({2, r}, Cell::Occupied);
    const GridAStar planner(grid);
    CPPUNIT_ASSERT_THROW(planner.plan({2, 1}, {0, 0}), rgnav::StartBlockedError);
    CPPUNIT_ASSERT_THROW(planner.plan({-1, 1}, {0, 0}), rgnav::StartBlockedError);
    CPPUNIT_ASSERT_THROW(planner.plan({0, 0}, {2, 3}), rgnav::GoalBlockedError);
    CPPUNIT_ASSERT_THROW(planner.plan({0, 0}, {4, 4}), rgnav::NoPathError);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.0, planner.plan({0, 0}, {0, 4}).length, 1e-12);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(GridAStarTest);
