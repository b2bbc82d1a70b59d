// Tests exploration end to end in process: the RG Mapping Kernel maps a synthetic hallway with two
// rooms (and one with four) behind doors (SyntheticTour.h: ray-cast scans, a fake door detector)
// while the robot drives the route planner's paths to the explorer's goals. Both strategies must
// pass every door (the kernel opens a region for each room: three or five regions, no gateway with
// an unknown side) and then say Done, within a bounded number of goals; with doors detected early,
// through at least one gateway goal. Prints each goal's reason and a summary line per run.
#include <cppunit/extensions/HelperMacros.h>

#include <cstdint>
#include <cstdio>
#include <utility>

#include "core/nav/exploration/Explorer.h"
#include "core/nav/exploration/PlannerPathLength.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/KernelPlanningMap.h"
#include "core/nav/planning/RoutePlanner.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"

using Eigen::Vector2d;

namespace {

// A hallway (x in [0, 20], y in [0, 2]) with four 4 m x 4 m rooms behind 0.9 m doors, two north
// and two south of it, at x in [2, 6] and [12, 16].
rgnav::testing::TourWorld hallwayWithFourRooms() {
  rgnav::testing::TourWorld w;
  w.walls = {{{0, 0}, {0, 2}}, {{20, 0}, {20, 2}}};
  for (const double y : {0.0, 2.0}) {
    w.walls.push_back({{0, y}, {3.55, y}});
    w.walls.push_back({{4.45, y}, {13.55, y}});
    w.walls.push_back({{14.45, y}, {20, y}});
    const double far = y == 0.0 ? -4.0 : 6.0;
    for (const double x0 : {2.0, 12.0}) {
      w.walls.push_back({{x0, y}, {x0, far}});
      w.walls.push_back({{x0 + 4, y}, {x0 + 4, far}});
      w.walls.push_back({{x0, far}, {x0 + 4, far}});
      const rgnav::DetectorGatewayId id{static_cast<std::uint64_t>(30 + w.doors.size())};
      w.doors.push_back({id, {x0 + 1.55, y}, {x0 + 2.45, y}, rgnav::testing::DoorReports::All});
    }
  }
  return w;
}

struct Outcome {
  bool done = false;
  std::size_t goals = 0, gatewayGoals = 0, regions = 0, openGateways = 0;
  double drivenM = 0.0;
};

Outcome explore(const std::string& strategy, double detectRangeM,
                rgnav::testing::TourWorld world = rgnav::testing::hallwayWithTwoRooms()) {
  constexpr std::size_t kMaxGoals = 40;
  const rgnav::ExplorationConfig config;
  rgnav::testing::SyntheticTour tour(std::move(world), rgnav::testing::kTourDrift, 0.25, detectRangeM);
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
    const rgnav::PathLength length = rgnav::plannerPathLength(planner, pose);
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
  void rgExplorationPassesBothDoorsAndFinishes() { exploresToTheEnd("rg"); }
  void nearestFrontierPassesBothDoorsAndFinishes() { exploresToTheEnd("frontier"); }

 private:
  // Doors detected late: the hallway's freespace reaches into the rooms through them, and a
  // frontier there leads the robot in. Detected early: the kernel cuts the freespace at the
  // doors, and the robot must drive through them as gateways.
  static void exploresToTheEnd(const std::string& strategy) {
    check(explore(strategy, 1.5));
    const Outcome early = explore(strategy, 3.0);
    check(early);
    CPPUNIT_ASSERT(early.gatewayGoals >= 1);
    check(explore(strategy, 3.0, hallwayWithFourRooms()), 5);
  }

  static void check(const Outcome& out, std::size_t regions = 3) {
    CPPUNIT_ASSERT(out.done);
    CPPUNIT_ASSERT_EQUAL(regions, out.regions);
    CPPUNIT_ASSERT_EQUAL(std::size_t(0), out.openGateways);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ExplorationTourTest);
