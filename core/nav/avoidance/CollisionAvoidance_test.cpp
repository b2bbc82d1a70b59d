// Tests the Collision Avoidance's decisions with a robot that follows its chains exactly: it
// drives the targets in free space, stops (or brakes short) when an obstacle appears on the chain
// it drives, goes around a box on its path, and reports blocked once walled in for
// blocked_wait_s, and leaves a room by its door when the path's later part (the hallway) lies
// just behind the wall it faces, keeps the target of a door it drove by (it turns back to it), and
// gets away from a wall it braked into, drives again when stopped short of the goal, and passes a
// person (a moving obstacle) slower than a post in the same place, and after 5 s held back by one
// who stays, takes it for standing; and it decides when one planning latency ahead lies a hair
// before its chain's end.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <vector>

#include "core/nav/avoidance/CollisionAvoidance.h"

using namespace rgnav;

namespace {

const Footprint kJackal = Footprint::rectangle(0.508, 0.43);

// 10 x 10 m of 5 cm cells around the origin, free, with the cells of the boxes occupied.
struct Box {
  double x0, y0, x1, y1;
};
ObstacleGrid gridWith(const std::vector<Box>& boxes, Timestamp stamp) {
  ObstacleGrid grid{"test", stamp, OccupancyGrid(200, 200, 0.05, {-5.0, -5.0}, Cell::Free), {}};
  for (const Box& b : boxes)
    for (double x = b.x0 + 0.025; x < b.x1; x += 0.05)
      for (double y = b.y0 + 0.025; y < b.y1; y += 0.05) grid.cells.set(*grid.cells.cellOf({x, y}), Cell::Occupied);
  return grid;
}

std::vector<Pose2D> straightTargets(double toX) {
  std::vector<Pose2D> targets;
  for (double x = 1.0; x <= toX + 1e-9; x += 1.0) targets.push_back({x, 0.0, 0.0});
  return targets;
}

// A robot that is exactly where its chain's reference is.
class PerfectRobot {
 public:
  explicit PerfectRobot(const MotionLimits& limits) : limits_(limits) {}
  RobotState at(Timestamp t) const {
    if (!chain_) return {t, standing_, 0.0, 0.0};
    const ReferenceState ref = timed_->stateAt(std::max(0.0, t - chain_->startTime));
    return {t, ref.pose, ref.velocity, ref.rotational};
  }
  void drive(const DriveChain& chain, Timestamp t) {
    standing_ = at(t).pose;
    chain_ = chain;
    timed_.emplace(chain.chain, limits_, chain.startSpeed, 0.0);
  }

 private:
  MotionLimits limits_;
  Pose2D standing_;
  std::optional<DriveChain> chain_;
  std::optional<TimedTrajectory> timed_;
};

}  // namespace

class CollisionAvoidanceTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CollisionAvoidanceTest);
  CPPUNIT_TEST(drivesTheTargetsInFreeSpace);
  CPPUNIT_TEST(stopsForAnObstacleAppearingOnItsChain);
  CPPUNIT_TEST(goesAroundABox);
  CPPUNIT_TEST(reportsBlockedWhenWalledIn);
  CPPUNIT_TEST(leavesARoomByItsDoorNotTowardsTheHallwayBehindItsWall);
  CPPUNIT_TEST(keepsTheDoorTargetItDroveBy);
  CPPUNIT_TEST(getsAwayFromTheWallItStandsAgainst);
  CPPUNIT_TEST(drivesAgainWhenStoppedShortOfTheGoal);
  CPPUNIT_TEST(passesAWalkingPersonSlowly);
  CPPUNIT_TEST(takesAPersonWhoStaysForAStandingObstacle);
  CPPUNIT_TEST(decidesWithTheReferenceAHairBeforeItsChainsEnd);
  CPPUNIT_TEST_SUITE_END();

 public:
  void drivesTheTargetsInFreeSpace() {
    CollisionAvoidance cam({}, kJackal, limits_);
    cam.setTargets(straightTargets(3.0));
    const AvoidanceDecision d = cam.update({0.0, {}, 0.0, 0.0}, std::span(&free_, 1));
    CPPUNIT_ASSERT(d.action == AvoidanceAction::Drive);
    CPPUNIT_ASSERT(d.chain);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.1, d.chain->startTime, 1e-9);  // one planning latency ahead
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.0, d.chain->chain.end().x, 1e-3);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, d.chain->chain.end().y, 1e-3);
    // Nothing changed: the chain is kept.
    CPPUNIT_ASSERT(cam.update({0.1, {}, 0.0, 0.0}, std::span(&free_, 1)).action == AvoidanceAction::Keep);
  }

  void stopsForAnObstacleAppearingOnItsChain() {
    CollisionAvoidance cam({}, kJackal, limits_);
    PerfectRobot robot(limits_);
    cam.setTargets(straightTargets(4.0));
    robot.drive(*cam.update(robot.at(0.0), std::span(&free_, 1)).chain, 0.0);
    // A wall across the way appears 2.5 m ahead while the robot drives.
    const ObstacleGrid walled = gridWith({{2.5, -5.0, 2.7, 5.0}}, 1.0);
    const RobotState state = robot.at(1.0);
    CPPUNIT_ASSERT(state.velocity > 0.3);
    const AvoidanceDecision d = cam.update(state, std::span(&walled, 1));
    CPPUNIT_ASSERT(d.action != AvoidanceAction::Keep);
    CPPUNIT_ASSERT(d.chain);
    // The new chain stops with the robot's front before the wall.
    const Pose2D end = d.chain->chain.end();
    CPPUNIT_ASSERT(end.x + 0.254 < 2.5);
    CPPUNIT_ASSERT(!kJackal.overlapsGrid(walled.cells, end));
  }

  void goesAroundABox() {
    CollisionAvoidance cam({}, kJackal, limits_);
    PerfectRobot robot(limits_);
    cam.setTargets(straightTargets(4.0));
    // A post between the targets at 1 and 2 m.
    const ObstacleGrid boxed = gridWith({{1.4, -0.2, 1.6, 0.2}}, 0.0);
    double aside = 0.0;
    bool reached = false;
    for (int i = 0; i < 300 && !reached; ++i) {
      const double t = 0.1 * i;
      const RobotState state = robot.at(t);
      const AvoidanceDecision d = cam.update(state, std::span(&boxed, 1));
      if (d.chain) robot.drive(*d.chain, t);
      reached = d.action == AvoidanceAction::GoalReached;
      CPPUNIT_ASSERT(!kJackal.overlapsGrid(boxed.cells, state.pose));
      aside = std::max(aside, std::abs(state.pose.y));
      CPPUNIT_ASSERT(d.action != AvoidanceAction::Blocked);
    }
    CPPUNIT_ASSERT(reached);
    CPPUNIT_ASSERT(aside > 0.3);  // it left the line to pass the post (and came back to the goal)
  }

  void reportsBlockedWhenWalledIn() {
    CollisionAvoidanceConfig config;
    config.blockedWaitS = 2.0;
    CollisionAvoidance cam(config, kJackal, limits_);
    cam.setTargets(straightTargets(3.0));
    // Walls all around, 0.35 m from the robot: too close to turn on the spot with the margin.
    const ObstacleGrid walled = gridWith(
        {{0.35, -1.0, 0.55, 1.0}, {-0.55, -1.0, -0.35, 1.0}, {-0.55, 0.35, 0.55, 0.55}, {-0.55, -0.55, 0.55, -0.35}}, 0.0);
    AvoidanceAction last = AvoidanceAction::Keep;
    double blockedAt = -1.0;
    for (int i = 0; i <= 30 && blockedAt < 0.0; ++i) {
      last = cam.update({0.1 * i, {}, 0.0, 0.0}, std::span(&walled, 1)).action;
      CPPUNIT_ASSERT(last == AvoidanceAction::Wait || last == AvoidanceAction::Blocked);
      if (last == AvoidanceAction::Blocked) blockedAt = 0.1 * i;
    }
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, blockedAt, 1e-6);
  }

  void leavesARoomByItsDoorNotTowardsTheHallwayBehindItsWall() {
    // A room (x -3..2, y -1..3) with its door in the east wall (y 0.5..1.5) onto a corridor (x 2..4)
    // that turns west into a hallway (y -3..-1) behind the room's south wall. The robot stands in
    // the room facing west; the path goes east through the door, south, then west along the hallway.
    const ObstacleGrid rooms = gridWith({{-5.0, -1.1, 4.1, -1.0},   // the room's south wall
                                         {-5.0, -3.1, 4.1, -3.0},   // the hallway's south wall
                                         {2.0, -1.0, 2.1, 0.5},     // the east wall, the door,
                                         {2.0, 1.5, 2.1, 3.1},
                                         {-3.1, -1.0, -3.0, 3.1},   // west and north walls
                                         {-3.0, 3.0, 2.0, 3.1},
                                         {4.0, -3.0, 4.1, 3.1}},    // the corridor's east wall
                                        0.0);
    std::vector<Pose2D> targets{{1.0, 1.0, 0.0}, {2.0, 1.0, 0.0}, {3.0, 1.0, -M_PI / 2}, {3.0, 0.0, -M_PI / 2},
                                {3.0, -1.0, -M_PI / 2}};
    for (double x = 3.0; x >= -4.0 - 1e-9; x -= 1.0) targets.push_back({x, -2.0, M_PI});
    CollisionAvoidance cam({}, kJackal, limits_);
    cam.setTargets(targets);
    const AvoidanceDecision d = cam.update({0.0, {0.0, 0.0, M_PI}, 0.0, 0.0}, std::span(&rooms, 1));
    CPPUNIT_ASSERT(d.action == AvoidanceAction::Drive);
    CPPUNIT_ASSERT(d.chain);
    CPPUNIT_ASSERT(d.chain->chain.end().x > 1.0);  // towards the door, not west
  }

  void getsAwayFromTheWallItStandsAgainst() {
    // A round robot braked into a hallway's wall (y -1.0 .. -1.1; the cells hit straddle y = -1) facing it;
    // its path runs along the hallway's middle.
    const Footprint disk = Footprint::disk(0.25);
    const ObstacleGrid walls = gridWith({{-5.0, -1.1, 5.0, -0.95}, {-5.0, 1.0, 5.0, 1.1}}, 0.0);
    std::vector<Pose2D> targets;
    for (double x = 0.5; x <= 4.0 + 1e-9; x += 0.5) targets.push_back({x, 0.0, 0.0});
    CollisionAvoidance cam({}, disk, limits_);
    cam.setTargets(targets);
    AvoidanceAction last = AvoidanceAction::Wait;
    for (int i = 0; i <= 40 && last != AvoidanceAction::Drive; ++i) {
      const AvoidanceDecision d = cam.update({0.1 * i, {0.0, -0.71, -1.66}, 0.0, 0.0}, std::span(&walls, 1));
      last = d.action;
    }
    CPPUNIT_ASSERT(last == AvoidanceAction::Drive);
  }

  void drivesAgainWhenStoppedShortOfTheGoal() {
    CollisionAvoidance cam({}, kJackal, limits_);
    cam.setTargets(straightTargets(2.0));
    const AvoidanceDecision first = cam.update({0.0, {}, 0.0, 0.0}, std::span(&free_, 1));
    CPPUNIT_ASSERT(first.chain);
    const double end = first.chain->startTime + TimedTrajectory(first.chain->chain, limits_).duration();
    // Something the robot cannot see stopped it 1 m short: it stands there.
    const RobotState stopped{end, {1.0, 0.0, 0.0}, 0.0, 0.0};
    CPPUNIT_ASSERT(cam.update(stopped, std::span(&free_, 1)).action == AvoidanceAction::Keep);  // settling
    RobotState later = stopped;
    later.stamp = end + 5.0;
    const AvoidanceDecision again = cam.update(later, std::span(&free_, 1));
    CPPUNIT_ASSERT(again.action == AvoidanceAction::Drive);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, again.chain->chain.end().x, 1e-3);
  }

  void passesAWalkingPersonSlowly() {
    // Something 0.5 m wide beside the path 2.5 m ahead, clear of the robot's way.
    ObstacleGrid beside = gridWith({{2.25, 0.6, 2.75, 1.1}}, 0.0);
    const auto topSpeed = [&](const ObstacleGrid& grid) {
      CollisionAvoidance cam({}, kJackal, limits_);
      cam.setTargets(straightTargets(4.0));
      const AvoidanceDecision d = cam.update({0.0, {}, 0.0, 0.0}, std::span(&grid, 1));
      CPPUNIT_ASSERT(d.action == AvoidanceAction::Drive);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(4.0, d.chain->chain.end().x, 1e-3);
      double top = 0.0;
      for (double s = 0.0; s < d.chain->chain.length(); s += 0.05)
        top = std::max(top, TimedTrajectory(d.chain->chain, limits_, 0.0, 0.0, d.chain->cruiseOrUnlimited()).speedAt(s));
      return top;
    };
    const double post = topSpeed(beside);
    beside.moving = beside.cells;  // now it is a person
    const double person = topSpeed(beside);
    CPPUNIT_ASSERT(post > 0.95);
    CPPUNIT_ASSERT(person < 0.7);
  }

  void takesAPersonWhoStaysForAStandingObstacle() {
    // Something the grid calls moving, 0.55 m beside the path just ahead of the standing robot.
    ObstacleGrid grid = gridWith({{0.4, 0.77, 0.9, 1.27}}, 0.0);
    grid.moving = grid.cells;
    CollisionAvoidance cam({}, kJackal, limits_);
    cam.setTargets(straightTargets(4.0));
    const AvoidanceDecision first = cam.update({0.0, {}, 0.0, 0.0}, std::span(&grid, 1));
    CPPUNIT_ASSERT(first.chain);
    CPPUNIT_ASSERT(first.chain->cruiseSpeed > 0.0 && first.chain->cruiseSpeed < 0.1);  // a crawl
    // The robot crawls; the same grid for 6 s: then the obstacle counts as standing.
    double cruise = first.chain->cruiseSpeed;
    for (int i = 1; i <= 60; ++i) {
      const AvoidanceDecision d = cam.update({0.1 * i, {}, 0.0, 0.0}, std::span(&grid, 1));
      if (d.chain) cruise = d.chain->cruiseSpeed;
    }
    CPPUNIT_ASSERT(cruise == 0.0 || cruise > 0.5);
  }

  void keepsTheDoorTargetItDroveBy() {
    // The path turns right at (2, 0) through a door to (2, -1) and on to (2, -2); the robot went
    // on 0.6 m past the turn: the hallway targets are passed, the door's is not.
    CollisionAvoidance cam({}, kJackal, limits_);
    cam.setTargets({{1.0, 0.0, 0.0}, {2.0, 0.0, -M_PI / 2}, {2.0, -1.0, -M_PI / 2}, {2.0, -2.0, -M_PI / 2}});
    cam.update({0.0, {2.6, -0.3, 0.0}, 0.0, 0.0}, std::span(&free_, 1));
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), cam.targets().size());
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-1.0, cam.targets().front().y, 1e-12);
  }

 private:
  // One planning latency ahead the reference lies a hair (less than a nanometre) before the end
  // of the chain: what is left of it slices to nothing, and the check of the speed for people
  // ahead must take that as nothing ahead (it once asked the empty slice for a pose and threw,
  // ending the exploration evaluation's run).
  void decidesWithTheReferenceAHairBeforeItsChainsEnd() {
    CollisionAvoidance cam({}, kJackal, limits_);
    cam.setTargets(straightTargets(8.0));  // farther than a chain reaches: the first ends short of the goal
    const AvoidanceDecision first = cam.update({0.0, {}, 0.0, 0.0}, std::span(&free_, 1));
    CPPUNIT_ASSERT(first.chain);
    PerfectRobot robot(limits_);
    robot.drive(*first.chain, 0.0);
    const double end = first.chain->startTime + TimedTrajectory(first.chain->chain, limits_).duration();
    const RobotState nearEnd = robot.at(end - CollisionAvoidanceConfig{}.planningLatencyS - 1e-6);
    const AvoidanceDecision next = cam.update(nearEnd, std::span(&free_, 1));
    CPPUNIT_ASSERT(next.action != AvoidanceAction::Blocked);
  }

  MotionLimits limits_;
  ObstacleGrid free_ = gridWith({}, 0.0);
};

CPPUNIT_TEST_SUITE_REGISTRATION(CollisionAvoidanceTest);
