// Tests the map-less goal seeking: targets lead around a wall with unknown space counting as
// free, 0.5-1.5 m apart, ending at the goal; a goal outside the grid is still the last target; a
// robot walled in gets none.
#include <cppunit/extensions/HelperMacros.h>

#include <array>
#include <cmath>
#include <vector>

#include "core/nav/avoidance/GoalSeeking.h"

using namespace rgnav;

namespace {

const Footprint kJackal = Footprint::rectangle(0.508, 0.43);

// 10 x 10 m of 5 cm cells around the origin, all Unknown, with the cells of the boxes occupied.
OccupancyGrid unknownWith(const std::vector<std::array<double, 4>>& boxes) {
  OccupancyGrid grid(200, 200, 0.05, {-5.0, -5.0}, Cell::Unknown);
  for (const auto& b : boxes)
    for (double x = b[0] + 0.025; x < b[2]; x += 0.05)
      for (double y = b[1] + 0.025; y < b[3]; y += 0.05) grid.set(*grid.cellOf({x, y}), Cell::Occupied);
  return grid;
}

}  // namespace

class GoalSeekingTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GoalSeekingTest);
  CPPUNIT_TEST(targetsLeadAroundAWallThroughUnknownSpace);
  CPPUNIT_TEST(aGoalOutsideTheGridIsTheLastTarget);
  CPPUNIT_TEST(aWalledInRobotGetsNoTargets);
  CPPUNIT_TEST_SUITE_END();

 public:
  void targetsLeadAroundAWallThroughUnknownSpace() {
    const GoalSeeking seeking({}, kJackal);
    // A wall across the way from y = -2 to 2 at x = 1.
    const OccupancyGrid grid = unknownWith({{1.0, -2.0, 1.2, 2.0}});
    const auto targets = seeking.plan(grid, {0.0, 0.0, 0.0}, {3.0, 0.0});
    CPPUNIT_ASSERT(targets && !targets->empty());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.0, targets->back().x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, targets->back().y, 1e-9);
    bool around = false;
    Pose2D previous{0.0, 0.0, 0.0};
    for (const Pose2D& t : *targets) {
      const double gap = std::hypot(t.x - previous.x, t.y - previous.y);
      CPPUNIT_ASSERT(gap <= 1.5 + 1e-6);
      around = around || std::abs(t.y) > 2.0;
      previous = t;
    }
    CPPUNIT_ASSERT(around);
  }

  void aGoalOutsideTheGridIsTheLastTarget() {
    const GoalSeeking seeking({}, kJackal);
    const auto targets = seeking.plan(unknownWith({}), {0.0, 0.0, 0.0}, {8.0, 0.0});
    CPPUNIT_ASSERT(targets);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(8.0, targets->back().x, 1e-9);
  }

  void aWalledInRobotGetsNoTargets() {
    const GoalSeeking seeking({}, kJackal);
    const OccupancyGrid grid =
        unknownWith({{0.5, -1.0, 0.7, 1.0}, {-0.7, -1.0, -0.5, 1.0}, {-0.7, 0.5, 0.7, 0.7}, {-0.7, -0.7, 0.7, -0.5}});
    CPPUNIT_ASSERT(!seeking.plan(grid, {0.0, 0.0, 0.0}, {3.0, 0.0}));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(GoalSeekingTest);
