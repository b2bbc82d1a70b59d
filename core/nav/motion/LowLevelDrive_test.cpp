// Tests the Low-Level Drive closed-loop with the simulated robot at 20 Hz (no odometry noise):
// it follows a chain and stops at its end within 2 cm and 1 degree, in about the predicted time;
// it pulls a robot standing beside the chain onto it; it predicts over commands that reach the
// robot late;
// it brakes within the limits when its odometry stops; a newer chain replaces the current one and
// older ids are refused; without a chain and after stop() it stands.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <deque>

#include "core/common/Errors.h"
#include "core/nav/motion/LowLevelDrive.h"
#include "core/sim/motion/DiffDriveRobot.h"

using rgnav::DiffDriveRobot;
using rgnav::DriveChain;
using rgnav::DriveState;
using rgnav::LowLevelDrive;
using rgnav::LowLevelDriveConfig;
using rgnav::OdometryReading;
using rgnav::Pose2D;
using rgnav::TrajectoryChain;

namespace {

constexpr double kDt = 0.05;

// The default limits are the simulated robot's.
LowLevelDriveConfig driveConfig() { return LowLevelDriveConfig{}; }

// A straight, a smooth left turn of 90 degrees, a straight.
TrajectoryChain turnChain(const Pose2D& start) {
  TrajectoryChain chain;
  chain.append({start, 1.0, 0.0, 0.0});
  chain.append({chain.end(), 0.5, 0.0, 2.0});
  chain.append({chain.end(), M_PI / 2.0 - 0.5, 1.0, 0.0});
  chain.append({chain.end(), 0.5, 1.0, -2.0});
  chain.append({chain.end(), 1.0, 0.0, 0.0});
  return chain;
}

// The simulated robot on a free 40 m square with the drive in the loop; time in ticks.
struct Rig {
  rgnav::OccupancyGrid grid{400, 400, 0.1, {-20.0, -20.0}};
  DiffDriveRobot robot{rgnav::DiffDriveConfig{}, {}};
  LowLevelDrive drive{driveConfig()};
  double now = 0.0;
  std::uint64_t readings = 0;
  bool odometry = true;
  OdometryReading last;
  rgnav::VelocityCommand command;
  std::deque<rgnav::VelocityCommand> inFlight;  // commands on their way to the robot

  void step() {
    if (odometry) last = {++readings, now, robot.pose(), robot.velocity().translational, robot.velocity().rotational};
    command = drive.tick(last, now);
    inFlight.push_back(command);
    robot.command(inFlight.front());
    inFlight.pop_front();
    robot.step(kDt, grid);
    now += kDt;
  }
  // Steps until the chain is finished or `seconds` have passed; returns the time taken.
  double runUntilFinished(double seconds) {
    const double start = now;
    while (!drive.status().chainFinished && now - start < seconds) step();
    return now - start;
  }
};

// The robot stands within 2 cm and 1 degree of the chain's end.
void assertStandsAtEnd(const TrajectoryChain& chain, const DiffDriveRobot& robot) {
  const Pose2D error = rgnav::between(chain.end(), robot.pose());
  CPPUNIT_ASSERT(std::hypot(error.x, error.y) <= 0.02);
  CPPUNIT_ASSERT(std::abs(error.theta) <= M_PI / 180.0);
  CPPUNIT_ASSERT_EQUAL(0.0, robot.velocity().translational);
}

}  // namespace

class LowLevelDriveTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LowLevelDriveTest);
  CPPUNIT_TEST(stopsAtChainEnd);
  CPPUNIT_TEST(recoversFromOffset);
  CPPUNIT_TEST(compensatesCommandDelay);
  CPPUNIT_TEST(brakesOnOdometryLoss);
  CPPUNIT_TEST(newerChainReplacesCurrent);
  CPPUNIT_TEST(standsWithoutChain);
  CPPUNIT_TEST(badConfigurationsAreRejected);
  CPPUNIT_TEST_SUITE_END();

 public:
  void stopsAtChainEnd() {
    Rig rig;
    const TrajectoryChain chain = turnChain({});
    rig.drive.setChain({1, chain, 0.0, 0.0});
    const double predicted = rgnav::TimedTrajectory(chain, rgnav::referenceLimits(driveConfig())).duration();
    double worstLateral = 0.0;
    while (!rig.drive.status().chainFinished && rig.now < 30.0) {
      rig.step();
      worstLateral = std::max(worstLateral, std::abs(rig.drive.status().lateralError));
    }
    CPPUNIT_ASSERT(rig.drive.status().chainFinished);
    CPPUNIT_ASSERT(rig.drive.status().state == DriveState::Idle);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(predicted, rig.now, 0.05 * predicted);
    assertStandsAtEnd(chain, rig.robot);
    CPPUNIT_ASSERT(worstLateral < 0.02);
    // It stays there.
    for (int k = 0; k < 20; ++k) rig.step();
    CPPUNIT_ASSERT_EQUAL(0.0, rig.command.translational);
    CPPUNIT_ASSERT_EQUAL(0.0, rig.command.rotational);
  }

  void recoversFromOffset() {
    // The robot stands 10 cm beside the chain's start, askew: the feedback pulls it onto the chain.
    Rig rig;
    rig.robot = DiffDriveRobot(rgnav::DiffDriveConfig{}, {0.0, 0.1, 0.1});
    const TrajectoryChain chain = turnChain({});
    rig.drive.setChain({1, chain, 0.0, 0.0});
    while (rig.now < 4.0) rig.step();
    CPPUNIT_ASSERT(rig.drive.status().state == DriveState::Tracking);
    CPPUNIT_ASSERT(std::abs(rig.drive.status().lateralError) < 0.005);
    rig.runUntilFinished(30.0);
    assertStandsAtEnd(chain, rig.robot);
  }

  void compensatesCommandDelay() {
    // The robot gets every command two ticks late; told so, the drive predicts over them (without
    // the prediction this loop swings out by metres).
    Rig rig;
    LowLevelDriveConfig config = driveConfig();
    config.commandDelayTicks = 2;
    rig.drive = LowLevelDrive(config);
    rig.inFlight.resize(2);
    const TrajectoryChain chain = turnChain({});
    rig.drive.setChain({1, chain, 0.0, 0.0});
    double worstLateral = 0.0;
    while (!rig.drive.status().chainFinished && rig.now < 30.0) {
      rig.step();
      worstLateral = std::max(worstLateral, std::abs(rig.drive.status().lateralError));
    }
    CPPUNIT_ASSERT(worstLateral < 0.01);
    assertStandsAtEnd(chain, rig.robot);
  }

  void brakesOnOdometryLoss() {
    Rig rig;
    TrajectoryChain chain;
    chain.append({{}, 10.0, 0.0, 0.0});
    rig.drive.setChain({1, chain, 0.0, 0.0});
    while (rig.now < 3.0) rig.step();
    const double speed = rig.robot.velocity().translational;
    CPPUNIT_ASSERT(speed > 0.9);
    rig.odometry = false;
    double previous = rig.command.translational;
    while (rig.now < 8.0) {
      rig.step();
      CPPUNIT_ASSERT(rig.command.translational <= previous + 1e-12);
      CPPUNIT_ASSERT(previous - rig.command.translational <= driveConfig().limits.maxDeceleration * kDt + 1e-9);
      previous = rig.command.translational;
    }
    CPPUNIT_ASSERT(rig.drive.status().state == DriveState::Idle);
    CPPUNIT_ASSERT(!rig.drive.status().chainFinished);
    CPPUNIT_ASSERT_EQUAL(0.0, rig.robot.velocity().translational);
    CPPUNIT_ASSERT(rig.robot.pose().x < 9.0);
    // Its odometry back, it does not resume the dropped chain.
    rig.odometry = true;
    for (int k = 0; k < 20; ++k) rig.step();
    CPPUNIT_ASSERT_EQUAL(0.0, rig.command.translational);
  }

  void newerChainReplacesCurrent() {
    Rig rig;
    TrajectoryChain straight;
    straight.append({{}, 10.0, 0.0, 0.0});
    rig.drive.setChain({5, straight, 0.0, 0.0});
    while (rig.now < 2.0) rig.step();
    // The replacement continues from where the reference is now, at its speed, and turns left.
    const rgnav::DriveStatus status = rig.drive.status();
    const rgnav::TimedTrajectory timed(straight, rgnav::referenceLimits(driveConfig()));
    const double t = rig.now;
    const rgnav::ReferenceState from = timed.stateAt(t);
    const TrajectoryChain turn = turnChain(from.pose);
    CPPUNIT_ASSERT_THROW(rig.drive.setChain({5, turn, from.velocity, t}), rgnav::InvalidArgumentError);
    rig.drive.setChain({6, turn, from.velocity, t});
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{6}, rig.drive.status().chainId);
    CPPUNIT_ASSERT(status.progress > 0.5);
    rig.runUntilFinished(30.0);
    CPPUNIT_ASSERT(rig.drive.status().chainFinished);
    assertStandsAtEnd(turn, rig.robot);
    // A stop planned just long enough at the full deceleration (1 m from 1 m/s) is taken without
    // the reference margin; a chain it cannot brake on at all is refused and the drive goes on.
    TrajectoryChain stop;
    stop.append({rig.robot.pose(), 1.0, 0.0, 0.0});
    CPPUNIT_ASSERT_THROW(rgnav::TimedTrajectory(stop, rgnav::referenceLimits(driveConfig()), 1.0),
                         rgnav::InvalidArgumentError);
    rig.drive.setChain({7, stop, 1.0, rig.now});
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{7}, rig.drive.status().chainId);
    TrajectoryChain stub;
    stub.append({rig.robot.pose(), 0.1, 0.0, 0.0});
    CPPUNIT_ASSERT_THROW(rig.drive.setChain({8, stub, 1.0, rig.now}), rgnav::InvalidArgumentError);
  }

  void standsWithoutChain() {
    Rig rig;
    for (int k = 0; k < 10; ++k) rig.step();
    CPPUNIT_ASSERT(rig.drive.status().state == DriveState::Idle);
    CPPUNIT_ASSERT_EQUAL(0.0, rig.command.translational);
    TrajectoryChain chain;
    chain.append({{}, 10.0, 0.0, 0.0});
    rig.drive.setChain({1, chain, 0.0, rig.now});
    while (rig.now < 3.0) rig.step();
    rig.drive.stop();
    rig.step();
    CPPUNIT_ASSERT(rig.drive.status().state == DriveState::Braking);
    while (rig.now < 7.0) rig.step();
    CPPUNIT_ASSERT(rig.drive.status().state == DriveState::Idle);
    CPPUNIT_ASSERT_EQUAL(0.0, rig.robot.velocity().translational);
  }

  void badConfigurationsAreRejected() {
    LowLevelDriveConfig config;
    config.periodSeconds = 0.0;
    CPPUNIT_ASSERT_THROW(LowLevelDrive{config}, rgnav::ConfigError);
    config = {};
    config.gains.kx = -1.0;
    CPPUNIT_ASSERT_THROW(LowLevelDrive{config}, rgnav::ConfigError);
    config = {};
    config.commandDelayTicks = 6;
    CPPUNIT_ASSERT_THROW(LowLevelDrive{config}, rgnav::ConfigError);
    config = {};
    config.referenceMargin = 0.6;
    CPPUNIT_ASSERT_THROW(LowLevelDrive{config}, rgnav::ConfigError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(LowLevelDriveTest);
