// Tests the two exploration strategies on small RG maps (ExplorationRooms.h). RG exploration:
// the current region's frontier before any gateway; then an untraversed door, driven through to a
// point past its line that the route planner plans to, not to the frontier the kernel's door cut
// leaves there; the gateway queue first-in first-out across regions, a traversed gateway leaving
// it; Done when nothing is left. Nearest frontier: the nearest by driving distance, not by
// straight line; an unreachable frontier and one failed maxGoalFailures times are skipped.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Errors.h"
#include "core/nav/exploration/NearestFrontierExploration.h"
#include "core/nav/exploration/RgExploration.h"
#include "core/nav/exploration/testing/ExplorationRooms.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/RoutePlanner.h"

using Eigen::Vector2d;
using rgnav::ExplorationGoal;
using rgnav::GatewayId;
using rgnav::PathLength;
using rgnav::Pose2D;
using rgnav::RegionId;
using rgnav::RegionView;
using rgnav::Segment2;
using rgnav::testing::door;
using rgnav::testing::exploredRegion;
using rgnav::testing::FreeRect;
using rgnav::testing::planningMap;

namespace {

using Kind = ExplorationGoal::Kind;
const RegionId kR1{1}, kR2{2}, kR3{3}, kNone{};

// A closed 4 m x 4 m room at x0..x0+4, y 0..4 (one region each); `doorLeft`, `doorRight`: a 0.8 m
// door in that wall at y 1.6..2.4, where its freespace reaches 0.3 m past the door as the kernel
// cuts it;
// `gapTop`: its top wall open between x0+1 and x0+3.
RegionView room(RegionId id, double x0, bool doorLeft, bool doorRight, bool gapTop = false) {
  const double x1 = x0 + 4.0;
  std::vector<Segment2> walls{{{x0, 0}, {x1, 0}}};
  const auto side = [&](double x, bool open) {
    if (open) {
      walls.push_back({{x, 0}, {x, 1.6}});
      walls.push_back({{x, 2.4}, {x, 4}});
    } else {
      walls.push_back({{x, 0}, {x, 4}});
    }
  };
  side(x0, doorLeft);
  side(x1, doorRight);
  if (gapTop) {
    walls.push_back({{x0, 4}, {x0 + 1, 4}});
    walls.push_back({{x0 + 3, 4}, {x1, 4}});
  } else {
    walls.push_back({{x0, 4}, {x1, 4}});
  }
  std::vector<FreeRect> free{{{x0, 0}, {x1, 4}}};
  if (doorLeft) free.push_back({{x0 - 0.3, 0.6}, {x0, 3.4}});
  if (doorRight) free.push_back({{x1, 0.6}, {x1 + 0.3, 3.4}});
  return exploredRegion(id, Pose2D{x0 + 0.3, 0.2, 0.1 * static_cast<double>(id.value())}, walls, free);
}

// A door in the wall x = x, y 1.6..2.4; side A on the left (smaller x).
rgnav::GatewayView doorAt(GatewayId id, double x, RegionId left, RegionId right) {
  return door(id, {x, 1.6}, {x, 2.4}, left, right);
}

PathLength straightLine(const Vector2d& robot) {
  return [robot](const Vector2d& goal) -> std::optional<double> { return (goal - robot).norm(); };
}

PathLength planned(const rgnav::RoutePlanner& planner, const Pose2D& robot) {
  return [&planner, robot](const Vector2d& goal) -> std::optional<double> {
    try {
      return planner.plan(robot, rgnav::PlanGoal::at(goal)).lengthM;
    } catch (const rgnav::NoPathError&) {
      return std::nullopt;
    }
  };
}

}  // namespace

class ExplorationStrategiesTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ExplorationStrategiesTest);
  CPPUNIT_TEST(rgCompletesTheCurrentRegionBeforeAnyGateway);
  CPPUNIT_TEST(rgDrivesThroughAnUntraversedDoorToAPlannablePoint);
  CPPUNIT_TEST(rgCompletesARoomItsHallwaySawInto);
  CPPUNIT_TEST(rgTakesGatewaysFirstInFirstOutAcrossRegions);
  CPPUNIT_TEST(rgDropsAGatewayFailedTooOften);
  CPPUNIT_TEST(rgIsDoneWhenNothingIsLeft);
  CPPUNIT_TEST(nearestFrontierIsNearestByDrivingDistance);
  CPPUNIT_TEST(nearestFrontierSkipsUnreachableAndFailedGoals);
  CPPUNIT_TEST(aDoorWithNoSideKnownIsDrivenThroughToItsUnexploredSide);
  CPPUNIT_TEST(aRobotThePlannerCannotStartFromDropsNothing);
  CPPUNIT_TEST(aFrontierSeenFromItsViewpointIsNotGivenAgain);
  CPPUNIT_TEST(strategiesByName);
  CPPUNIT_TEST_SUITE_END();

 public:
  void rgCompletesTheCurrentRegionBeforeAnyGateway() {
    const auto map = planningMap({room(kR1, 0.0, false, true, true)}, {doorAt(GatewayId{1}, 4.0, kR1, kNone)});
    rgnav::RoutePlanner planner;
    planner.setMap(map);
    const Pose2D robot{3.2, 2.0, 0.0};  // nearer the door than the gap
    rgnav::RgExploration rg({});
    const ExplorationGoal goal = rg.next({map, robot, kR1}, planned(planner, robot));
    CPPUNIT_ASSERT(goal.kind == Kind::Frontier);
    CPPUNIT_ASSERT(goal.region == kR1);
    CPPUNIT_ASSERT((goal.point - Vector2d(2.0, 3.4)).norm() < 0.3);  // below the gap in the top wall
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), rg.queue().size());
    CPPUNIT_ASSERT(!goal.reason.empty());
  }

  void rgDrivesThroughAnUntraversedDoorToAPlannablePoint() {
    const auto map = planningMap({room(kR1, 0.0, false, true)}, {doorAt(GatewayId{1}, 4.0, kR1, kNone)});
    rgnav::RoutePlanner planner;
    planner.setMap(map);
    const Pose2D robot{1.0, 1.0, 0.0};
    rgnav::RgExploration rg({});
    const PathLength length = planned(planner, robot);
    const ExplorationGoal goal = rg.next({map, robot, kR1}, length);
    CPPUNIT_ASSERT(goal.kind == Kind::Gateway);  // not the frontier of the freespace past the door
    CPPUNIT_ASSERT(goal.gateway == GatewayId{1});
    CPPUNIT_ASSERT(goal.region.isNone());
    CPPUNIT_ASSERT(goal.point.x() > 4.05 && goal.point.x() <= 4.5);  // past the door's line
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, goal.point.y(), 1e-9);
    CPPUNIT_ASSERT(length(goal.point).has_value());
  }

  void rgCompletesARoomItsHallwaySawInto() {
    // Region 1 saw most of room 2 through door 1 before the door was known: its freespace covers
    // the room up to x = 7.5 and, through the gap in room 2's top wall, a little beyond, so the
    // frontier there is region 1's by its cells. In room 2, it is room 2's to complete before
    // door 2 (open, in region 1's left wall).
    const std::vector<Segment2> walls{{{0, 0}, {4, 0}}, {{0, 4}, {4, 4}}, {{0, 0}, {0, 1.6}},
                                      {{0, 2.4}, {0, 4}}, {{4, 0}, {4, 1.6}}, {{4, 2.4}, {4, 4}}};
    const RegionView r1 = exploredRegion(kR1, {}, walls, {{{-0.3, 0.6}, {0.0, 3.4}}, {{0.0, 0.0}, {4.0, 4.0}}, {{4.0, 0.0}, {7.5, 4.3}}});
    const auto map = planningMap({r1, room(kR2, 4.0, true, false, true)},
                                 {doorAt(GatewayId{1}, 4.0, kR1, kR2), doorAt(GatewayId{2}, 0.0, kNone, kR1)});
    rgnav::RgExploration rg({});
    const ExplorationGoal goal = rg.next({map, {6.0, 2.0, 0.0}, kR2}, straightLine({6.0, 2.0}));
    CPPUNIT_ASSERT(goal.kind == Kind::Frontier);
    CPPUNIT_ASSERT(goal.region == kR2);
    CPPUNIT_ASSERT(goal.point.x() > 4.5 && goal.point.x() < 7.0);  // below the gap, in room 2
    CPPUNIT_ASSERT(goal.point.y() > 3.3 && goal.point.y() < 3.9);
  }

  void rgTakesGatewaysFirstInFirstOutAcrossRegions() {
    // Regions 1 and 2 joined by door 1; door 5 leads on from region 2, seen first.
    const auto r1 = room(kR1, 0.0, false, true), r2 = room(kR2, 4.0, true, true);
    const auto d1 = doorAt(GatewayId{1}, 4.0, kR1, kR2);
    rgnav::RgExploration rg({});
    const Pose2D inR1{1.0, 2.0, 0.0};
    auto map = planningMap({r1, r2}, {d1, doorAt(GatewayId{5}, 8.0, kR2, kNone)});
    CPPUNIT_ASSERT(rg.next({map, inR1, kR1}, straightLine({1.0, 2.0})).gateway == GatewayId{5});
    // Door 4 in region 1's left wall, seen later, nearer, with a lower ID: queued behind door 5.
    const RegionView r1WithDoor = room(kR1, 0.0, true, true);
    map = planningMap({r1WithDoor, r2}, {d1, doorAt(GatewayId{4}, 0.0, kNone, kR1), doorAt(GatewayId{5}, 8.0, kR2, kNone)});
    const ExplorationGoal second = rg.next({map, inR1, kR1}, straightLine({1.0, 2.0}));
    CPPUNIT_ASSERT(second.gateway == GatewayId{5});
    CPPUNIT_ASSERT(second.point.x() > 8.0);
    CPPUNIT_ASSERT(rg.queue() == std::deque<GatewayId>({GatewayId{5}, GatewayId{4}}));
    // Door 5 traversed into region 3, a closed room: door 4 is next, from region 3.
    map = planningMap({r1WithDoor, r2, room(kR3, 8.0, true, false)},
                      {d1, doorAt(GatewayId{4}, 0.0, kNone, kR1), doorAt(GatewayId{5}, 8.0, kR2, kR3)});
    const ExplorationGoal third = rg.next({map, {10.0, 2.0, 0.0}, kR3}, straightLine({10.0, 2.0}));
    CPPUNIT_ASSERT(third.kind == Kind::Gateway);
    CPPUNIT_ASSERT(third.gateway == GatewayId{4});
    CPPUNIT_ASSERT(third.point.x() < 0.0);  // past door 4, on its unknown side
    CPPUNIT_ASSERT(rg.queue() == std::deque<GatewayId>({GatewayId{4}}));
  }

  void rgDropsAGatewayFailedTooOften() {
    const auto map = planningMap({room(kR1, 0.0, false, true)}, {doorAt(GatewayId{1}, 4.0, kR1, kNone)});
    rgnav::RgExploration rg({});  // maxGoalFailures = 2
    const Pose2D robot{1.0, 2.0, 0.0};
    const ExplorationGoal goal = rg.next({map, robot, kR1}, straightLine({1.0, 2.0}));
    rg.failed(goal);
    CPPUNIT_ASSERT(rg.next({map, robot, kR1}, straightLine({1.0, 2.0})) == goal);
    rg.failed(goal);
    CPPUNIT_ASSERT(rg.queue().empty());
    CPPUNIT_ASSERT(rg.next({map, robot, kR1}, straightLine({1.0, 2.0})).kind == Kind::Done);
  }

  void rgIsDoneWhenNothingIsLeft() {
    const auto map = planningMap({room(kR1, 0.0, false, true), room(kR2, 4.0, true, false)},
                                 {doorAt(GatewayId{1}, 4.0, kR1, kR2)});
    rgnav::RgExploration rg({});
    const ExplorationGoal goal = rg.next({map, {6.0, 2.0, 0.0}, kR2}, straightLine({6.0, 2.0}));
    CPPUNIT_ASSERT(goal.kind == Kind::Done);
    CPPUNIT_ASSERT(rg.queue().empty());
  }

  void nearestFrontierIsNearestByDrivingDistance() {
    // Two gaps in the top walls of two rooms side by side (one region each, joined by door 1).
    const auto map = planningMap({room(kR1, 0.0, false, true, true), room(kR2, 4.0, true, false, true)},
                                 {doorAt(GatewayId{1}, 4.0, kR1, kR2)});
    const Vector2d robot(3.0, 1.0);
    rgnav::NearestFrontierExploration nearest({});
    const ExplorationGoal byLine = nearest.next({map, {3.0, 1.0, 0.0}, kR1}, straightLine(robot));
    CPPUNIT_ASSERT(byLine.kind == Kind::Frontier && byLine.region == kR1);
    // Region 1's gap is a long way round: the one in region 2 is nearer by driving.
    const PathLength detour = [robot](const Vector2d& goal) -> std::optional<double> {
      return (goal - robot).norm() + (goal.x() < 4.0 ? 10.0 : 0.0);
    };
    const ExplorationGoal byPath = nearest.next({map, {3.0, 1.0, 0.0}, kR1}, detour);
    CPPUNIT_ASSERT(byPath.kind == Kind::Frontier && byPath.region == kR2);
    CPPUNIT_ASSERT((byPath.point - Vector2d(6.0, 3.4)).norm() < 0.3);
  }

  void nearestFrontierSkipsUnreachableAndFailedGoals() {
    const auto map = planningMap({room(kR1, 0.0, false, true, true), room(kR2, 4.0, true, false, true)},
                                 {doorAt(GatewayId{1}, 4.0, kR1, kR2)});
    const Vector2d robot(3.0, 1.0);
    const PathLength regionTwoOnly = [robot](const Vector2d& goal) -> std::optional<double> {
      if (goal.x() < 4.0 && (goal - robot).norm() > 0.01) return std::nullopt;
      return (goal - robot).norm();
    };
    rgnav::NearestFrontierExploration nearest({});
    CPPUNIT_ASSERT(nearest.next({map, {3.0, 1.0, 0.0}, kR1}, regionTwoOnly).region == kR2);
    const ExplorationGoal first = nearest.next({map, {3.0, 1.0, 0.0}, kR1}, straightLine(robot));
    CPPUNIT_ASSERT(first.region == kR1);
    nearest.failed(first);
    CPPUNIT_ASSERT(nearest.next({map, {3.0, 1.0, 0.0}, kR1}, straightLine(robot)) == first);
    nearest.failed(first);
    CPPUNIT_ASSERT(nearest.next({map, {3.0, 1.0, 0.0}, kR1}, straightLine(robot)).region == kR2);
  }

  void aDoorWithNoSideKnownIsDrivenThroughToItsUnexploredSide() {
    // The door seen from afar: no side attached yet, and the hallway's freespace reaches 0.3 m
    // past it. Its unexplored side is x > 4 wherever the robot stands.
    const auto map = planningMap({room(kR1, 0.0, false, true)}, {doorAt(GatewayId{1}, 4.0, kNone, kNone)});
    for (const Vector2d& robot : {Vector2d(1.0, 2.0), Vector2d(4.15, 3.2)}) {  // the second nearer x > 4
      rgnav::RgExploration rg({});
      const ExplorationGoal goal = rg.next({map, {robot.x(), robot.y(), 0.0}, kR1}, straightLine(robot));
      CPPUNIT_ASSERT(goal.kind == Kind::Gateway);
      CPPUNIT_ASSERT(goal.point.x() > 4.05);
    }
  }

  void aRobotThePlannerCannotStartFromDropsNothing() {
    // Nothing plans, not even to the robot's own position: the straight line stands in.
    const auto map = planningMap({room(kR1, 0.0, false, true, true)}, {doorAt(GatewayId{1}, 4.0, kR1, kNone)});
    const PathLength nothing = [](const Vector2d&) { return std::optional<double>(); };
    rgnav::RgExploration rg({});
    const ExplorationGoal goal = rg.next({map, {2.0, 2.0, 0.0}, kR1}, nothing);
    CPPUNIT_ASSERT(goal.kind == Kind::Frontier);
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), rg.queue().size());
    // Where the robot's position plans, nothing else does: all is unreachable, and that is Done.
    const PathLength onlyHere = [](const Vector2d& p) {
      return (p - Vector2d(2.0, 2.0)).norm() < 1e-9 ? std::optional<double>(0.0) : std::nullopt;
    };
    CPPUNIT_ASSERT(rg.next({map, {2.0, 2.0, 0.0}, kR1}, onlyHere).kind == Kind::Done);
    CPPUNIT_ASSERT(rg.queue().empty());
  }

  void aFrontierSeenFromItsViewpointIsNotGivenAgain() {
    const auto map = planningMap({room(kR1, 0.0, false, true, true), room(kR2, 4.0, true, false, true)},
                                 {doorAt(GatewayId{1}, 4.0, kR1, kR2)});
    rgnav::NearestFrontierExploration nearest({});
    const ExplorationGoal first = nearest.next({map, {3.0, 1.0, 0.0}, kR1}, straightLine({3.0, 1.0}));
    CPPUNIT_ASSERT(first.region == kR1);
    // The robot reached it and the frontier is still there (the map did not change): the other.
    const Vector2d there = first.point;
    CPPUNIT_ASSERT(nearest.next({map, {there.x(), there.y(), 0.0}, kR1}, straightLine(there)).region == kR2);
  }

  void strategiesByName() {
    CPPUNIT_ASSERT_EQUAL(std::string("rg"), rgnav::makeExplorationStrategy("rg", {})->name());
    CPPUNIT_ASSERT_EQUAL(std::string("frontier"), rgnav::makeExplorationStrategy("frontier", {})->name());
    CPPUNIT_ASSERT_THROW(rgnav::makeExplorationStrategy("random", {}), rgnav::ConfigError);
    rgnav::ExplorationConfig bad;
    bad.maxGoalFailures = 0;
    CPPUNIT_ASSERT_THROW(rgnav::makeExplorationStrategy("rg", bad), rgnav::ConfigError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ExplorationStrategiesTest);
