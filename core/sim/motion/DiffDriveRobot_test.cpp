// Tests the simulated base: straight driving under acceleration limits, exact arcs, velocity
// limits, the disk footprint, stopping at the last free pose on a collision, the rectangle
// footprint (its front, its corners when turning on the spot) and round obstacles (people).
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/nav/grid/DiskFootprint.h"
#include "core/sim/motion/DiffDriveRobot.h"
#include "core/sim/scenarios/GridDrawing.h"

using rgnav::Cell;
using rgnav::DiffDriveConfig;
using rgnav::DiffDriveRobot;
using rgnav::DiskObstacle;
using rgnav::Footprint;
using rgnav::OccupancyGrid;
using rgnav::StepOutcome;

namespace {

// 4 x 4 m at 5 cm, free inside, walls of 0.2 m on every side.
OccupancyGrid boxWorld() {
  OccupancyGrid grid(80, 80, 0.05, {0.0, 0.0}, Cell::Occupied);
  rgnav::fillRect(grid, {0.2, 0.2, 3.8, 3.8}, Cell::Free);
  return grid;
}

OccupancyGrid openWorld() { return OccupancyGrid(400, 400, 0.05, {-10.0, -10.0}); }

// Accelerations high enough that every command is reached within one step.
DiffDriveConfig instantConfig() {
  DiffDriveConfig c;
  c.maxTranslationalAcceleration = 1e6;
  c.maxRotationalAcceleration = 1e6;
  return c;
}

}  // namespace

class DiffDriveRobotTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(DiffDriveRobotTest);
  CPPUNIT_TEST(straightLineWithAccelerationRamp);
  CPPUNIT_TEST(arcIsExact);
  CPPUNIT_TEST(turnOnTheSpot);
  CPPUNIT_TEST(commandsAreClampedToLimits);
  CPPUNIT_TEST(diskFootprintIsExact);
  CPPUNIT_TEST(collisionStopsAtLastFreePose);
  CPPUNIT_TEST(rectangleStopsWithItsFrontAtTheWall);
  CPPUNIT_TEST(rectangleCornersCollideWhenTurning);
  CPPUNIT_TEST(roundObstaclesStopTheRobot);
  CPPUNIT_TEST(badInputIsTypedError);
  CPPUNIT_TEST_SUITE_END();

 public:
  void straightLineWithAccelerationRamp() {
    const OccupancyGrid grid = openWorld();
    DiffDriveRobot robot(DiffDriveConfig{}, {0.0, 0.0, 0.0});  // 0.5 m/s^2
    robot.command({0.5, 0.0});
    for (int k = 1; k <= 30; ++k) {
      CPPUNIT_ASSERT(robot.step(0.1, grid) == StepOutcome::Moved);
      if (k <= 10) {
        CPPUNIT_ASSERT_DOUBLES_EQUAL(0.05 * k, robot.velocity().translational, 1e-12);
      }
    }
    // Ramp: 0.1 s * 0.05 * (1 + ... + 10) = 0.275 m, then 20 steps at 0.05 m.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.275, robot.pose().x, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, robot.pose().y, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, robot.pose().theta, 1e-12);
  }

  void arcIsExact() {
    const OccupancyGrid grid = openWorld();
    DiffDriveRobot robot(instantConfig(), {0.0, 0.0, 0.0});
    const double v = 0.8, w = 0.4;  // circle of radius 2 about (0, 2)
    robot.command({v, w});
    for (int k = 1; k <= 100; ++k) {
      robot.step(0.13, grid);
      const double a = w * 0.13 * k;
      CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0 * std::sin(a), robot.pose().x, 1e-9);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0 - 2.0 * std::cos(a), robot.pose().y, 1e-9);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, rgnav::normalizeAngle(a - robot.pose().theta), 1e-9);
    }
  }

  void turnOnTheSpot() {
    const OccupancyGrid grid = openWorld();
    DiffDriveRobot robot(instantConfig(), {1.0, 2.0, 0.5});
    robot.command({0.0, -1.0});
    robot.step(0.5, grid);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, robot.pose().x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, robot.pose().y, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, robot.pose().theta, 1e-12);
  }

  void commandsAreClampedToLimits() {
    const OccupancyGrid grid = openWorld();
    DiffDriveConfig config;
    config.maxTranslationalVelocity = 0.7;
    config.maxRotationalVelocity = 0.9;
    config.maxTranslationalAcceleration = 0.4;
    config.maxRotationalAcceleration = 0.6;
    DiffDriveRobot robot(config, {});
    robot.command({5.0, -5.0});
    robot.step(0.5, grid);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.2, robot.velocity().translational, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-0.3, robot.velocity().rotational, 1e-12);
    for (int k = 0; k < 20; ++k) {
      robot.step(0.5, grid);
    }
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.7, robot.velocity().translational, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-0.9, robot.velocity().rotational, 1e-12);
    robot.command({-5.0, 0.0});
    robot.step(0.5, grid);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.5, robot.velocity().translational, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-0.6, robot.velocity().rotational, 1e-12);
  }

  void diskFootprintIsExact() {
    const OccupancyGrid grid = boxWorld();  // free x, y in [0.2, 3.8]
    CPPUNIT_ASSERT(!rgnav::diskCollides(grid, {2.0, 2.0}, 0.25));
    CPPUNIT_ASSERT(!rgnav::diskCollides(grid, {0.45, 2.0}, 0.25));   // touches the wall
    CPPUNIT_ASSERT(rgnav::diskCollides(grid, {0.449, 2.0}, 0.25));
    // Beside the corner of a block: the nearest blocked point is the corner (2.5, 2.5).
    OccupancyGrid block = boxWorld();
    rgnav::fillRect(block, {2.0, 2.0, 2.5, 2.5}, Cell::Occupied);
    const double d = 0.25 / std::sqrt(2.0);
    CPPUNIT_ASSERT(!rgnav::diskCollides(block, {2.5 + d + 1e-6, 2.5 + d + 1e-6}, 0.25));
    CPPUNIT_ASSERT(rgnav::diskCollides(block, {2.5 + d - 1e-3, 2.5 + d - 1e-3}, 0.25));
    // Beyond the grid counts as blocked.
    const OccupancyGrid open(20, 20, 0.05);
    CPPUNIT_ASSERT(rgnav::diskCollides(open, {0.1, 0.5}, 0.2));
  }

  void collisionStopsAtLastFreePose() {
    const OccupancyGrid grid = boxWorld();  // wall face at x = 3.8
    DiffDriveRobot robot(DiffDriveConfig{}, {2.0, 2.0, 0.0});
    robot.command({1.0, 0.0});
    StepOutcome outcome = StepOutcome::Moved;
    int steps = 0;
    while (outcome == StepOutcome::Moved && steps < 1000) {
      outcome = robot.step(0.1, grid);
      ++steps;
    }
    CPPUNIT_ASSERT(outcome == StepOutcome::Collided);
    const double limit = 3.8 - 0.25;
    CPPUNIT_ASSERT(robot.pose().x <= limit + 1e-9);
    CPPUNIT_ASSERT(robot.pose().x >= limit - 0.05 / 4.0 - 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, robot.pose().y, 1e-12);
    CPPUNIT_ASSERT_EQUAL(0.0, robot.velocity().translational);
    CPPUNIT_ASSERT(!rgnav::diskCollides(grid, {robot.pose().x, robot.pose().y}, 0.25));
    // The collision also cleared the command: the robot does not push on.
    const rgnav::Pose2D stopped = robot.pose();
    CPPUNIT_ASSERT(robot.step(0.1, grid) == StepOutcome::Moved);
    CPPUNIT_ASSERT(stopped == robot.pose());
    // Pushing again collides at once without moving; backing off works.
    robot.command({0.5, 0.0});
    CPPUNIT_ASSERT(robot.step(0.1, grid) == StepOutcome::Collided);
    CPPUNIT_ASSERT(stopped == robot.pose());
    robot.command({-0.5, 0.0});
    CPPUNIT_ASSERT(robot.step(0.1, grid) == StepOutcome::Moved);
    CPPUNIT_ASSERT(robot.pose().x < stopped.x);
  }

  void rectangleStopsWithItsFrontAtTheWall() {
    const OccupancyGrid grid = boxWorld();  // wall face at x = 3.8
    DiffDriveConfig config;
    config.footprint = Footprint::rectangle(0.508, 0.430, 0.05);  // front 0.304 m ahead
    DiffDriveRobot robot(config, {2.0, 2.0, 0.0});
    robot.command({1.0, 0.0});
    int steps = 0;
    while (robot.step(0.1, grid) == StepOutcome::Moved && steps < 1000) ++steps;
    const double limit = 3.8 - 0.304;
    CPPUNIT_ASSERT(robot.pose().x <= limit + 1e-9);
    CPPUNIT_ASSERT(robot.pose().x >= limit - 0.05 / 4.0 - 1e-9);
    CPPUNIT_ASSERT(!robot.collidesAt(robot.pose(), grid));
    // Backwards the rear (0.204 m behind) meets the wall at x = 0.2.
    robot.command({-1.0, 0.0});
    while (robot.step(0.1, grid) == StepOutcome::Moved && steps < 2000) ++steps;
    CPPUNIT_ASSERT(robot.pose().x >= 0.2 + 0.204 - 1e-9);
    CPPUNIT_ASSERT(robot.pose().x <= 0.2 + 0.204 + 0.05 / 4.0 + 1e-9);
  }

  void rectangleCornersCollideWhenTurning() {
    const OccupancyGrid grid = boxWorld();
    DiffDriveConfig config = instantConfig();
    config.footprint = Footprint::rectangle(0.508, 0.430);  // corners 0.333 m from the centre
    // 0.3 m from the wall: free facing it, but the corners sweep 0.333 m out when turning. One
    // long step turns by 1 rad at once: the check in between must find the corner.
    DiffDriveRobot robot(config, {3.5, 2.0, 0.0});
    CPPUNIT_ASSERT(!robot.collidesAt(robot.pose(), grid));
    robot.command({0.0, 1.0});
    CPPUNIT_ASSERT(robot.step(1.0, grid) == StepOutcome::Collided);
    CPPUNIT_ASSERT(robot.pose().theta > 0.0 && robot.pose().theta < 0.6);
    CPPUNIT_ASSERT(!robot.collidesAt(robot.pose(), grid));
    // A disk robot of the rectangle's half width turns freely there.
    DiffDriveConfig round = instantConfig();
    round.footprint = Footprint::disk(0.215);
    DiffDriveRobot disk(round, {3.5, 2.0, 0.0});
    disk.command({0.0, 1.0});
    CPPUNIT_ASSERT(disk.step(1.0, grid) == StepOutcome::Moved);
  }

  void roundObstaclesStopTheRobot() {
    const OccupancyGrid grid = openWorld();
    DiffDriveConfig config;
    config.footprint = Footprint::rectangle(0.5, 0.4);
    DiffDriveRobot robot(config, {0.0, 0.0, 0.0});
    const DiskObstacle person{{2.0, 0.1}, 0.25};
    robot.command({1.0, 0.0});
    int steps = 0;
    while (robot.step(0.1, grid, {&person, 1}) == StepOutcome::Moved && steps < 1000) ++steps;
    const double limit = 2.0 - 0.25 - 0.25;  // the front edge against the person's side
    CPPUNIT_ASSERT(robot.pose().x <= limit + 1e-9);
    CPPUNIT_ASSERT(robot.pose().x >= limit - 0.05 / 4.0 - 1e-9);
    CPPUNIT_ASSERT(robot.collidesAt({limit + 0.01, 0.0, 0.0}, grid, {&person, 1}));
    CPPUNIT_ASSERT(!robot.collidesAt({limit + 0.01, 0.0, 0.0}, grid));
  }

  void badInputIsTypedError() {
    const OccupancyGrid grid = openWorld();
    DiffDriveConfig bad;
    bad.footprint = Footprint::disk(0.0);
    CPPUNIT_ASSERT_THROW(DiffDriveRobot(bad, {}), rgnav::ConfigError);
    bad = DiffDriveConfig{};
    bad.maxRotationalAcceleration = NAN;
    CPPUNIT_ASSERT_THROW(DiffDriveRobot(bad, {}), rgnav::ConfigError);
    DiffDriveRobot robot(DiffDriveConfig{}, {});
    CPPUNIT_ASSERT_THROW(robot.step(0.0, grid), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(robot.step(INFINITY, grid), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(robot.command({NAN, 0.0}), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(DiffDriveRobotTest);
