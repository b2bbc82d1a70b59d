// Tests the exploration grid and its frontiers on small RG maps (ExplorationRooms.h): free,
// wall and unknown cells through rotated region frames, the lowest region where freespaces
// overlap; a frontier along an open side and none along walls, its region, middle and a
// viewpoint the route planner plans to; a frontier longer than the useful range cut into pieces;
// clusters below minCells dropped; an empty map.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>

#include "core/common/Errors.h"
#include "core/nav/exploration/ExplorationGrid.h"
#include "core/nav/exploration/Frontiers.h"
#include "core/nav/exploration/testing/ExplorationRooms.h"
#include "core/nav/planning/RoutePlanner.h"

using Eigen::Vector2d;
using rgnav::ExplorationCell;
using rgnav::ExplorationGrid;
using rgnav::Frontier;
using rgnav::RegionId;
using rgnav::testing::exploredRegion;
using rgnav::testing::planningMap;

namespace {

const rgnav::Pose2D kTilted{1.0, -0.5, 0.4};

// A 4 m x 4 m room at the origin, walled on three sides, its top side open: the robot saw the
// floor up to y = 4 and nothing beyond.
rgnav::PlanningMap openTopRoom() {
  return planningMap({exploredRegion(RegionId{1}, kTilted, {{{0, 0}, {4, 0}}, {{0, 0}, {0, 4}}, {{4, 0}, {4, 4}}},
                                     {{{0, 0}, {4, 4}}})},
                     {});
}

ExplorationCell cellAt(const ExplorationGrid& grid, const Vector2d& p) {
  int col = 0, row = 0;
  return grid.cellOf(p, col, row) ? grid.at(col, row) : ExplorationCell::Unknown;
}

RegionId regionAt(const ExplorationGrid& grid, const Vector2d& p) {
  int col = 0, row = 0;
  return grid.cellOf(p, col, row) ? grid.regionAt(col, row) : RegionId{};
}

}  // namespace

class ExplorationGridTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ExplorationGridTest);
  CPPUNIT_TEST(cellsAreFreeWallOrUnknownInTheMapFrame);
  CPPUNIT_TEST(overlappingFreespaceBelongsToTheLowestRegion);
  CPPUNIT_TEST(aFrontierLiesAlongTheOpenSideOnly);
  CPPUNIT_TEST(theViewpointIsAGoalThePlannerAccepts);
  CPPUNIT_TEST(aFrontierLongerThanTheUsefulRangeIsCut);
  CPPUNIT_TEST(smallClustersAreNoFrontier);
  CPPUNIT_TEST(anEmptyMapGivesAnEmptyGrid);
  CPPUNIT_TEST_SUITE_END();

 public:
  void cellsAreFreeWallOrUnknownInTheMapFrame() {
    const ExplorationGrid grid = ExplorationGrid::fromMap(openTopRoom(), {});
    CPPUNIT_ASSERT(cellAt(grid, {2.0, 2.0}) == ExplorationCell::Free);
    CPPUNIT_ASSERT(regionAt(grid, {2.0, 2.0}) == RegionId{1});
    CPPUNIT_ASSERT(cellAt(grid, {0.05, 2.0}) == ExplorationCell::Wall);   // inside, near the left wall
    CPPUNIT_ASSERT(cellAt(grid, {-0.07, 2.0}) == ExplorationCell::Wall);  // outside, near it
    CPPUNIT_ASSERT(cellAt(grid, {2.0, 0.1}) == ExplorationCell::Wall);
    CPPUNIT_ASSERT(regionAt(grid, {2.0, 0.1}).isNone());
    CPPUNIT_ASSERT(cellAt(grid, {2.0, 4.5}) == ExplorationCell::Unknown);
    CPPUNIT_ASSERT(cellAt(grid, {-1.0, 2.0}) == ExplorationCell::Unknown);
    CPPUNIT_ASSERT(grid.at(-1, -1) == ExplorationCell::Unknown);
    // About the room's floor less the wall band: 16 m² less ~3 x 4 m x 0.2 m, at 0.01 m² a cell.
    CPPUNIT_ASSERT(grid.freeCount() > 1200 && grid.freeCount() < 1600);
    int col = 0, row = 0;
    CPPUNIT_ASSERT(grid.cellOf({2.0, 2.0}, col, row));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, grid.wallDistanceM(col, row), 0.1);
  }

  void overlappingFreespaceBelongsToTheLowestRegion() {
    const auto map = planningMap({exploredRegion(RegionId{2}, kTilted, {}, {{{3, 0}, {7, 4}}}),
                                  exploredRegion(RegionId{1}, {}, {}, {{{0, 0}, {4, 4}}})},
                                 {});
    const ExplorationGrid grid = ExplorationGrid::fromMap(map, {});
    CPPUNIT_ASSERT(regionAt(grid, {1.0, 2.0}) == RegionId{1});
    CPPUNIT_ASSERT(regionAt(grid, {3.5, 2.0}) == RegionId{1});
    CPPUNIT_ASSERT(regionAt(grid, {5.0, 2.0}) == RegionId{2});
    CPPUNIT_ASSERT(std::isinf(grid.wallDistanceM(1, 1)));  // no lines at all
  }

  void aFrontierLiesAlongTheOpenSideOnly() {
    const ExplorationGrid grid = ExplorationGrid::fromMap(openTopRoom(), {});
    const std::vector<Frontier> frontiers = rgnav::findFrontiers(grid, {});
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), frontiers.size());
    const Frontier& f = frontiers[0];
    CPPUNIT_ASSERT(f.region == RegionId{1});
    for (const Vector2d& c : f.cells) CPPUNIT_ASSERT(c.y() > 3.8 && c.y() < 4.2 && c.x() > 0.1 && c.x() < 3.9);
    CPPUNIT_ASSERT(f.lengthM() > 3.0 && f.lengthM() < 4.5);
    CPPUNIT_ASSERT((f.middle - Vector2d(2.0, 4.0)).norm() < 0.25);
  }

  void theViewpointIsAGoalThePlannerAccepts() {
    const auto map = openTopRoom();
    const ExplorationGrid grid = ExplorationGrid::fromMap(map, {});
    const Frontier f = rgnav::findFrontiers(grid, {}, 0.25).at(0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.6, (f.viewpoint - f.middle).norm(), 0.15);
    CPPUNIT_ASSERT(f.viewpoint.y() < f.middle.y());  // into the room
    int col = 0, row = 0;
    CPPUNIT_ASSERT(grid.cellOf(f.viewpoint, col, row) && grid.at(col, row) == ExplorationCell::Free);
    CPPUNIT_ASSERT(grid.wallDistanceM(col, row) >= rgnav::goalClearanceM(grid, 0.25));
    rgnav::RoutePlanner planner;
    planner.setMap(map);
    const rgnav::Plan plan = planner.plan({2.0, 1.0, 0.0}, rgnav::PlanGoal::at(f.viewpoint));
    CPPUNIT_ASSERT((plan.path.back() - f.viewpoint).norm() < 1e-9);
  }

  void aFrontierLongerThanTheUsefulRangeIsCut() {
    const auto map = planningMap({exploredRegion(RegionId{1}, {}, {{{0, 0}, {10, 0}}, {{0, 0}, {0, 3}}, {{10, 0}, {10, 3}}},
                                                 {{{0, 0}, {10, 3}}})},
                                 {});
    rgnav::FrontierConfig config;
    config.usefulRangeM = 4.0;
    const std::vector<Frontier> frontiers = rgnav::findFrontiers(ExplorationGrid::fromMap(map, {}), config);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), frontiers.size());
    for (const Frontier& f : frontiers) CPPUNIT_ASSERT(f.lengthM() <= 4.0 && f.lengthM() > 2.0);
    for (std::size_t i = 1; i < frontiers.size(); ++i)
      CPPUNIT_ASSERT(frontiers[i - 1].cells.size() >= frontiers[i].cells.size());
  }

  void smallClustersAreNoFrontier() {
    rgnav::FrontierConfig config;
    config.minCells = 60;  // more than the 4 m open side holds
    CPPUNIT_ASSERT(rgnav::findFrontiers(ExplorationGrid::fromMap(openTopRoom(), {}), config).empty());
  }

  void anEmptyMapGivesAnEmptyGrid() {
    const ExplorationGrid grid = ExplorationGrid::fromMap({}, {});
    CPPUNIT_ASSERT_EQUAL(0, grid.width());
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), grid.freeCount());
    CPPUNIT_ASSERT(rgnav::findFrontiers(grid, {}).empty());
    rgnav::ExplorationGridConfig bad;
    bad.resolutionM = 0.0;
    CPPUNIT_ASSERT_THROW(ExplorationGrid::fromMap(openTopRoom(), bad), rgnav::ConfigError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ExplorationGridTest);
