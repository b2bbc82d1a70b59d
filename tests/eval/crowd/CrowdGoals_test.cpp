// CrowdGoals on the office world: the asked number of goals, each in a room other than the
// previous goal's, on a cell with the clearance, far enough from the previous goal (and the start),
// the same for a seed and different for another; a world with a single room has no goals.
#include <cppunit/extensions/HelperMacros.h>

#include "core/nav/grid/ClearanceMap.h"
#include "core/sim/LoadedWorld.h"
#include "tests/eval/crowd/CrowdGoals.h"

using namespace rgnav;

class CrowdGoalsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CrowdGoalsTest);
  CPPUNIT_TEST(goalsKeepTheirRules);
  CPPUNIT_TEST(seedDecides);
  CPPUNIT_TEST(oneRoomHasNoGoals);
  CPPUNIT_TEST_SUITE_END();

 public:
  void goalsKeepTheirRules() {
    const LoadedWorld world = loadWorld("config/worlds/office.yaml");
    const Pose2D start{1.5, 7.0, 0.0};
    CrowdGoalOptions options;
    const auto goals = crowdGoals(world.grid, *world.truth, start, options);
    CPPUNIT_ASSERT_EQUAL(std::size_t(20), goals.size());
    const ClearanceMap clearance(world.grid);
    Eigen::Vector2d previous(start.x, start.y);
    int previousRoom = world.truth->roomAt({start.x, start.y});
    for (const Eigen::Vector2d& g : goals) {
      const int room = world.truth->roomAt({g.x(), g.y()});
      CPPUNIT_ASSERT(room >= 0);
      CPPUNIT_ASSERT(room != previousRoom);
      CPPUNIT_ASSERT(clearance.at(*world.grid.cellOf({g.x(), g.y()})) >= options.clearanceM);
      CPPUNIT_ASSERT((g - previous).norm() >= options.minSpacingM);
      previous = g;
      previousRoom = room;
    }
  }

  void seedDecides() {
    const LoadedWorld world = loadWorld("config/worlds/office.yaml");
    CrowdGoalOptions options;
    options.count = 5;
    const auto a = crowdGoals(world.grid, *world.truth, {1.5, 7.0, 0.0}, options);
    CPPUNIT_ASSERT(a == crowdGoals(world.grid, *world.truth, {1.5, 7.0, 0.0}, options));
    options.seed = 2;
    CPPUNIT_ASSERT(a != crowdGoals(world.grid, *world.truth, {1.5, 7.0, 0.0}, options));
  }

  void oneRoomHasNoGoals() {
    OccupancyGrid grid(100, 100, 0.05);
    GroundTruth truth;
    truth.width = truth.height = 100;
    truth.labels.assign(100 * 100, 0);
    truth.roomCount = 1;
    CPPUNIT_ASSERT_THROW(crowdGoals(grid, truth, {2.5, 2.5, 0.0}, {}), InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(CrowdGoalsTest);
