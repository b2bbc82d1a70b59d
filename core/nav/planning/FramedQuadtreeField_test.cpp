// Tests the framed-quadtree planner's fields: on random grids the field's cost from a point to the
// target is the graph distance (never below what plan() finds, which is any-angle, and never below
// the straight line), the path read off it runs free from the point to the target and is no longer
// than that cost, a point not connected to the target has no cost, and with wall costs the field's
// cost is the wall-weighted one (at least the path's length).
#include <cppunit/extensions/HelperMacros.h>

#include <random>

#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/testing/RandomGrids.h"
#include "core/nav/planning/FramedQuadtreePlanner.h"
#include "core/nav/planning/SegmentVisibility.h"

using Eigen::Vector2d;
using rgnav::Cell;
using rgnav::CellIndex;
using rgnav::FramedQuadtreePlanner;
using rgnav::OccupancyGrid;
using rgnav::testing::randomGrid;
using rgnav::testing::randomFreePoint;

class FramedQuadtreeFieldTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(FramedQuadtreeFieldTest);
  CPPUNIT_TEST(fieldPathsAreFreeAndNoLongerThanTheirCost);
  CPPUNIT_TEST(wallCostsWeighTheFieldsCost);
  CPPUNIT_TEST(blockedTargetsAndPointsAreRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void fieldPathsAreFreeAndNoLongerThanTheirCost() {
    std::mt19937 rng(5);
    std::size_t compared = 0, unconnected = 0;
    for (int trial = 0; trial < 20; ++trial) {
      const OccupancyGrid grid = randomGrid(rng, 40, 0.25);
      const FramedQuadtreePlanner planner(grid);
      const Vector2d target = randomFreePoint(rng, grid);
      const FramedQuadtreePlanner::Field field = planner.fieldTo(target);
      for (int k = 0; k < 20; ++k) {
        const Vector2d p = randomFreePoint(rng, grid);
        const auto cost = planner.costTo(field, p);
        bool planned = true;
        double planLength = 0.0;
        try {
          planLength = planner.plan(p, target).length;
        } catch (const rgnav::NoPathError&) {
          planned = false;
        }
        CPPUNIT_ASSERT_EQUAL(planned, cost.has_value());
        if (!cost) {
          ++unconnected;
          CPPUNIT_ASSERT_THROW(planner.pathTo(field, p), rgnav::NoPathError);
          continue;
        }
        ++compared;
        CPPUNIT_ASSERT(*cost >= planLength - 1e-9);
        CPPUNIT_ASSERT(*cost >= (target - p).norm() - 1e-9);
        const rgnav::CellUnitPath path = planner.pathTo(field, p);
        CPPUNIT_ASSERT(path.points.front() == p);
        CPPUNIT_ASSERT(path.points.back() == target);
        for (std::size_t i = 1; i < path.points.size(); ++i)
          CPPUNIT_ASSERT(rgnav::segmentFree(grid, path.points[i - 1], path.points[i]));
        CPPUNIT_ASSERT(path.length <= *cost + 1e-9);
      }
    }
    CPPUNIT_ASSERT(compared > 200);
    CPPUNIT_ASSERT(unconnected > 0);
  }

  void wallCostsWeighTheFieldsCost() {
    // A 40 x 9 corridor: along its wall a path pays the wall cost, so the field's cost from one
    // end to the other exceeds the straight length.
    OccupancyGrid grid(40, 11, 1.0, {}, Cell::Occupied);
    for (int r = 1; r <= 9; ++r)
      for (int c = 0; c < 40; ++c) grid.set({c, r}, Cell::Free);
    const FramedQuadtreePlanner planner(grid, {.wallCostDistanceM = 4.0, .wallCostWeight = 1.0});
    const Vector2d target(39.5, 1.5), from(0.5, 1.5);
    const auto field = planner.fieldTo(target);
    const double cost = *planner.costTo(field, from);
    const rgnav::CellUnitPath path = planner.pathTo(field, from);
    CPPUNIT_ASSERT(cost > (target - from).norm() * 1.05);
    CPPUNIT_ASSERT(path.length <= cost);
    double highest = 0.0;
    for (const Vector2d& q : path.points) highest = std::max(highest, q.y());
    CPPUNIT_ASSERT(highest >= 4.0);  // it leaves the wall for the corridor's middle
  }

  void blockedTargetsAndPointsAreRefused() {
    OccupancyGrid grid(10, 10, 1.0);
    grid.set({5, 5}, Cell::Occupied);
    const FramedQuadtreePlanner planner(grid);
    CPPUNIT_ASSERT_THROW(planner.fieldTo({5.5, 5.5}), rgnav::GoalBlockedError);
    const auto field = planner.fieldTo({1.5, 1.5});
    CPPUNIT_ASSERT(!planner.costTo(field, {5.5, 5.5}));
    CPPUNIT_ASSERT(!planner.costTo(field, {-3.0, 1.0}));
    CPPUNIT_ASSERT_THROW(planner.pathTo(field, {5.5, 5.5}), rgnav::NoPathError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(FramedQuadtreeFieldTest);
