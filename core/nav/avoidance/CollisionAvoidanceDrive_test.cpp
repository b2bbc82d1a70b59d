// Tests the Collision Avoidance in the loop, in process and in lock-step: the simulator (the
// round robot of config/sim/default.yaml: 0.25 m disk, 180-degree laser) driven by the Low-Level
// Drive, the laser obstacle grid and the Collision Avoidance following given targets in a
// generated office: a 2 m hallway, a cross hallway it must turn into at speed, and a 0.8 m door
// into a room beside the hallway, with targets as the RG planner places them (close to walls).
// The robot must reach the last target without ever being blocked by a wall.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <vector>

#include "core/nav/avoidance/CollisionAvoidance.h"
#include "core/nav/avoidance/CollisionAvoidanceConfigYaml.h"
#include "core/nav/avoidance/LaserObstacleMap.h"
#include "core/nav/motion/LowLevelDrive.h"
#include "core/nav/motion/LowLevelDriveConfigYaml.h"
#include "core/sim/Simulation.h"
#include "core/sim/SimulationConfigYaml.h"

using namespace rgnav;

namespace {

struct Rect {
  double x0, y0, x1, y1;
};

// 24 x 12 m, walls everywhere but the free rectangles: the hallway (y 6..8), the cross hallway
// (x 13..15, south from it), a room (y 3.5..5.9) with a 0.8 m door at x 9.6..10.4 through the
// 0.1 m wall between it and the hallway, and one west of the cross hallway (x 11.15..12.85) with
// a 0.9 m door at y 2.55..3.45 through a 0.15 m wall.
OccupancyGrid office() {
  OccupancyGrid grid(480, 240, 0.05, {0.0, 0.0}, Cell::Occupied);
  const std::vector<Rect> free{{1.0, 6.0, 22.0, 8.0},   {13.0, 1.0, 15.0, 8.0},  {7.0, 3.5, 11.0, 5.9},
                               {9.6, 5.9, 10.4, 6.0},   {11.15, 0.5, 12.85, 5.9}, {12.85, 2.55, 13.0, 3.45}};
  for (const Rect& r : free)
    for (double x = r.x0 + 0.025; x < r.x1; x += 0.05)
      for (double y = r.y0 + 0.025; y < r.y1; y += 0.05) grid.set(*grid.cellOf({x, y}), Cell::Free);
  return grid;
}

// Targets along the polyline, about `spacing` apart, each heading to the next (as
// core/nav/planning/TargetSpacing.h places them; the goal keeps the last stretch's heading).
std::vector<Pose2D> targetsAlong(const std::vector<WorldPoint>& corners, double spacing) {
  std::vector<Pose2D> out;
  for (std::size_t i = 1; i < corners.size(); ++i) {
    const WorldPoint a = corners[i - 1], b = corners[i];
    const int n = std::max(1, static_cast<int>(std::round(std::hypot(b.x - a.x, b.y - a.y) / spacing)));
    for (int k = 1; k <= n; ++k) out.push_back({a.x + (b.x - a.x) * k / n, a.y + (b.y - a.y) * k / n, 0.0});
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Pose2D& from = i + 1 < out.size() ? out[i] : (i > 0 ? out[i - 1] : out[i]);
    const Pose2D& to = i + 1 < out.size() ? out[i + 1] : out[i];
    out[i].theta = std::atan2(to.y - from.y, to.x - from.x);
  }
  return out;
}

struct DriveOutcome {
  bool reached = false;
  std::uint64_t collisions = 0;
  double seconds = 0.0;
};

// Drives from `start` along the targets for at most `limitS` simulated seconds (the odometry
// frame is the world frame: the robot starts there, and the noise is small over a run).
DriveOutcome driveAlong(const OccupancyGrid& world, const Pose2D& start, const std::vector<Pose2D>& targets,
                        double limitS) {
  const SimulationConfig simConfig = loadSimulationConfig("config/sim/default.yaml");
  const LowLevelDriveConfig driveConfig = loadLowLevelDriveConfig("config/modules/lowleveldrive.yaml");
  const CollisionAvoidanceConfig config = loadCollisionAvoidanceConfig("config/modules/collisionavoidance.yaml");
  const bool trace = std::getenv("RGNAV_TRACE") != nullptr;
  Simulation sim(world, simConfig, start);
  LowLevelDrive drive(driveConfig);
  LaserObstacleMap obstacles(config.obstacleMap);
  CollisionAvoidance cam(config, simConfig.robot.footprint, referenceLimits(driveConfig));
  cam.setTargets(targets);
  DriveOutcome outcome;
  std::optional<DriveChain> pending;
  while (sim.time() < limitS) {
    const SimulationStep step = sim.step();
    if (step.scan) {
      obstacles.add(*step.scan);
      const RobotState state{step.odometry.stamp, step.odometry.pose, step.odometry.translationalVelocity,
                             step.odometry.rotationalVelocity};
      const ObstacleGrid grid = obstacles.grid();
      const AvoidanceDecision decision = cam.update(state, std::span<const ObstacleGrid>(&grid, 1));
      if (trace && decision.action != AvoidanceAction::Keep)
        std::printf("# t=%.2f true=(%.2f %.2f %.2f) v=%.2f %s: %s%s\n", sim.time(), step.truePose.x, step.truePose.y,
                    step.truePose.theta, state.velocity, toString(decision.action).c_str(), decision.reason.c_str(),
                    decision.chain ? (" length=" + std::to_string(decision.chain->chain.length())).c_str() : "");
      if (decision.action == AvoidanceAction::GoalReached) {
        outcome.reached = true;
        break;
      }
      if (decision.action == AvoidanceAction::Blocked) cam.setTargets(targets);
      if (decision.chain) pending = decision.chain;
      if (decision.stopNow) {
        pending.reset();
        drive.stop();
      }
    }
    if (pending && step.odometry.stamp >= pending->startTime - 1e-9) {
      drive.setChain(*pending);
      pending.reset();
    }
    sim.command(drive.tick(step.odometry, step.odometry.stamp));
  }
  outcome.collisions = sim.robotCollisions();
  outcome.seconds = sim.time();
  return outcome;
}

// Prints the drive's outcome under `name` and asserts it reached the goal without a collision.
void expectReachedWithoutCollision(const char* name, const DriveOutcome& out) {
  std::printf("\n%s: reached=%d collisions=%llu t=%.1f s\n", name, out.reached,
              static_cast<unsigned long long>(out.collisions), out.seconds);
  CPPUNIT_ASSERT_MESSAGE(name, out.reached);
  CPPUNIT_ASSERT_EQUAL_MESSAGE(name, std::uint64_t{0}, out.collisions);
}

}  // namespace

class CollisionAvoidanceDriveTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CollisionAvoidanceDriveTest);
  CPPUNIT_TEST(turnsIntoTheCrossHallway);
  CPPUNIT_TEST(passesTheDoor);
  CPPUNIT_TEST(turnsIntoADoorFromTheCrossHallway);
  CPPUNIT_TEST(leavesTheRoomBehindItThroughTheDoor);
  CPPUNIT_TEST_SUITE_END();

 public:
  void turnsIntoTheCrossHallway() {
    // East along the hallway 0.4 m from its south wall, then south into the cross hallway.
    const std::vector<Pose2D> targets = targetsAlong({{2.0, 6.4}, {13.4, 6.4}, {13.4, 2.0}}, 1.0);
    const DriveOutcome out = driveAlong(world_, {2.0, 6.4, 0.0}, targets, 60.0);
    expectReachedWithoutCollision("corner", out);
  }

  void passesTheDoor() {
    // East along the hallway, then south through the door into the room.
    const std::vector<Pose2D> targets = targetsAlong({{5.0, 7.0}, {10.0, 7.0}, {10.0, 6.4}, {10.0, 4.0}}, 0.6);
    const DriveOutcome out = driveAlong(world_, {5.0, 7.0, 0.0}, targets, 60.0);
    expectReachedWithoutCollision("door", out);
  }

  void turnsIntoADoorFromTheCrossHallway() {
    // East along the hallway, south down the cross hallway close to its west wall, west through
    // the door beside it.
    const std::vector<Pose2D> targets =
        targetsAlong({{8.0, 7.0}, {13.4, 6.6}, {13.4, 3.0}, {12.2, 3.0}, {11.6, 1.5}}, 1.0);
    const DriveOutcome out = driveAlong(world_, {8.0, 7.0, 0.0}, targets, 60.0);
    expectReachedWithoutCollision("side door", out);
  }

  void leavesTheRoomBehindItThroughTheDoor() {
    // Standing in the room facing away from the door, the first targets behind it.
    const std::vector<Pose2D> targets = targetsAlong({{11.9, 1.9}, {12.2, 3.0}, {13.4, 3.0}, {13.4, 6.0}}, 0.6);
    const DriveOutcome out = driveAlong(world_, {11.9, 1.9, -2.0}, targets, 40.0);
    expectReachedWithoutCollision("leave room", out);
  }

 private:
  const OccupancyGrid world_ = office();
};

CPPUNIT_TEST_SUITE_REGISTRATION(CollisionAvoidanceDriveTest);
