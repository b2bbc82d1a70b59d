// Tests exploration end to end in process: the RG Mapping Kernel maps a synthetic hallway with two
// rooms behind doors (SyntheticTour.h: ray-cast scans, a fake door detector) while the robot
// drives the route planner's paths to the explorer's goals. Both strategies must pass both doors
// (the kernel opens a region for each room: three regions, no gateway with an unknown side) and
// then say Done, within a bounded number of goals; with doors detected early, through at least
// one gateway goal. Prints each goal's reason and a summary line per run.
#include <cppunit/extensions/HelperMacros.h>

#include <cstdio>

#include "core/nav/exploration/Explorer.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/KernelPlanningMap.h"
#include "core/nav/planning/RoutePlanner.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"

using Eigen::Vector2d;

namespace {

struct Outcome {
  bool done = false;
  std::size_t goals = 0, gatewayGoals = 0, regions = 0, openGateways = 0;
  double drivenM = 0.0;
};

Outcome explore(const std::string& strategy, double detectRangeM) {
  constexpr std::size_t kMaxGoals = 40;
  const rgnav::ExplorationConfig config;
  rgnav::testing::SyntheticTour tour(rgnav::testing::hallwayWithTwoRooms(), rgnav::testing::kTourDrift, 0.25, detectRangeM);
  Vector2d robot(1.0, 0.9);
  tour.driveThrough({robot, {2.0, 0.9}});
  robot = {2.0, 0.9};
  rgnav::RgMappingKernel kernel;
  std::size_t fed = 0;
  const auto feedNew = [&] {
    for (; fed < tour.inputs().size(); ++fed) rgnav::testing::feed(kernel, tour.inputs()[fed]);
  };
  feedNew();
  rgnav::Explorer explorer(rgnav::makeExplorationStrategy(strategy, config), config);
  rgnav::RoutePlanner planner;
  rgnav::DriveOutcome drive = rgnav::DriveOutcome::None;
  Outcome out;
  for (double now = 0.0; !explorer.done() && explorer.goalsGiven() < kMaxGoals; now += 10.0) {
    planner.setMap(rgnav::planningMapOf(kernel));
    const rgnav::Pose2D pose{robot.x(), robot.y(), 0.0};
    const rgnav::PathLength length = [&](const Vector2d& goal) -> std::optional<double> {
      try {
        return planner.plan(pose, rgnav::PlanGoal::at(goal)).lengthM;
      } catch (const rgnav::NoPathError&) {
        return std::nullopt;
      }
    };
    const rgnav::ExplorerStep step =
        explorer.update({planner.map(), pose, rgnav::mapSummary(kernel).current}, drive, now, length);
    if (step.action != rgnav::ExplorerStep::Action::DriveTo) continue;
    std::printf("%s goal %zu: %s\n", strategy.c_str(), explorer.goalsGiven(), step.goal.reason.c_str());
    out.gatewayGoals += step.goal.kind == rgnav::ExplorationGoal::Kind::Gateway;
    try {
      const rgnav::Plan plan = planner.plan(pose, rgnav::PlanGoal::at(step.goal.point));
      tour.driveThrough(plan.path);
      feedNew();
      robot = plan.path.back();
      out.drivenM += plan.lengthM;
      drive = rgnav::DriveOutcome::Reached;
    } catch (const rgnav::NoPathError&) {
      drive = rgnav::DriveOutcome::Failed;
    }
  }
  out.done = explorer.done();
  out.goals = explorer.goalsGiven();
  const rgnav::PlanningMap map = rgnav::planningMapOf(kernel);
  out.regions = map.regions.size();
  for (const rgnav::GatewayView& g : map.gateways) out.openGateways += g.sideA.isNone() || g.sideB.isNone();
  std::printf("%s, doors detected from %.1f m: done %d after %zu goals (%zu through gateways), %.1f m driven, %zu regions, "
              "%zu gateways open\n",
              strategy.c_str(), detectRangeM, out.done, out.goals, out.gatewayGoals, out.drivenM, out.regions, out.openGateways);
  return out;
}

}  // namespace

class ExplorationTourTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ExplorationTourTest);
  CPPUNIT_TEST(rgExplorationPassesBothDoorsAndFinishes);
  CPPUNIT_TEST(nearestFrontierPassesBothDoorsAndFinishes);
  CPPUNIT_TEST_SUITE_END();

 public:
  // Doors detected late: the hallway's freespace reaches into the rooms through them, and a
  // frontier there leads the robot in. Detected early: the kernel cuts the freespace at the
  // doors, and the robot must drive through them as gateways.
  void rgExplorationPassesBothDoorsAndFinishes() {
    check(explore("rg", 1.5));
    const Outcome early = explore("rg", 3.0);
    check(early);
    CPPUNIT_ASSERT(early.gatewayGoals >= 1);
  }

  void nearestFrontierPassesBothDoorsAndFinishes() {
    check(explore("frontier", 1.5));
    const Outcome early = explore("frontier", 3.0);
    check(early);
    CPPUNIT_ASSERT(early.gatewayGoals >= 1);
  }

 private:
  static void check(const Outcome& out) {
    CPPUNIT_ASSERT(out.done);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), out.regions);
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), out.openGateways);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ExplorationTourTest);
