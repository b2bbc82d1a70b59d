// Tests the velocity profile: the trapezoid of a straight against its closed form; on a chain of
// straights, clothoids and arcs every limit holds at every moment (sampled at 1 ms); the
// predicted time matches a drive that integrates the profile's speeds; time and arc length
// invert each other; a turn on the spot shorter than a grid step is timed; curvature jumps are
// passed slowly enough for the rotational acceleration; start speeds the chain
// cannot take or brake from are rejected; a cruise speed below the top speed holds after braking
// down to it from a faster start.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/nav/motion/TimedTrajectory.h"

using rgnav::MotionLimits;
using rgnav::ReferenceState;
using rgnav::TimedTrajectory;
using rgnav::TrajectoryChain;

namespace {

// A straight, a left turn (clothoid, arc, clothoid), a right clothoid into a sharper one and out.
TrajectoryChain mixedChain() {
  TrajectoryChain chain;
  chain.append({{0.0, 0.0, 0.0}, 1.5, 0.0, 0.0});
  chain.append({chain.end(), 1.0, 0.0, 1.0});
  chain.append({chain.end(), 1.0, 1.0, 0.0});
  chain.append({chain.end(), 1.0, 1.0, -1.0});
  chain.append({chain.end(), 0.6, 0.0, -3.0});
  chain.append({chain.end(), 0.6, -1.8, 3.0});
  chain.append({chain.end(), 2.0, 0.0, 0.0});
  return chain;
}

}  // namespace

class TimedTrajectoryTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(TimedTrajectoryTest);
  CPPUNIT_TEST(straightIsATrapezoid);
  CPPUNIT_TEST(everyLimitHolds);
  CPPUNIT_TEST(predictionMatchesIntegratedDrive);
  CPPUNIT_TEST(timeAndArcLengthInvert);
  CPPUNIT_TEST(turnOnTheSpotIsTimed);
  CPPUNIT_TEST(curvatureJumpsAreSlowed);
  CPPUNIT_TEST(startSpeedsAreChecked);
  CPPUNIT_TEST(cruiseSpeedHoldsAfterBraking);
  CPPUNIT_TEST_SUITE_END();

 public:
  void straightIsATrapezoid() {
    TrajectoryChain chain;
    chain.append({{0.0, 0.0, 0.0}, 4.0, 0.0, 0.0});
    const TimedTrajectory timed(chain, MotionLimits{});
    // 2 s up to 1 m/s over 1 m, 2 m at 1 m/s, 2 s down.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(6.0, timed.duration(), 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.5, timed.stateAt(1.0).velocity, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.25, timed.stateAt(1.0).s, 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, timed.speedAt(2.0), 1e-9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(4.0, timed.stateAt(100.0).s, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, timed.endSpeed(), 1e-12);
    // From a start speed of 1 m/s: 3 m at 1 m/s, then 2 s down.
    const TimedTrajectory moving(chain, MotionLimits{}, 1.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(5.0, moving.duration(), 1e-9);
  }

  void everyLimitHolds() {
    MotionLimits m;
    m.maxRotationalAcceleration = 1.2;
    m.maxLateralAcceleration = 0.8;
    const TimedTrajectory timed(mixedChain(), m, 0.2);
    const double dt = 1e-3, tol = 1e-6;
    ReferenceState before = timed.stateAt(0.0);
    double fastest = 0.0;
    for (double t = dt; t <= timed.duration(); t += dt) {
      const ReferenceState now = timed.stateAt(t);
      const double kappa = timed.chain().curvatureAt(now.s);
      CPPUNIT_ASSERT(now.velocity <= m.maxVelocity + tol);
      CPPUNIT_ASSERT(std::abs(now.rotational) <= m.maxRotationalVelocity + tol);
      CPPUNIT_ASSERT(now.velocity * now.velocity * std::abs(kappa) <= m.maxLateralAcceleration + tol);
      const double a = (now.velocity - before.velocity) / dt;
      CPPUNIT_ASSERT(a <= m.maxAcceleration + 1e-3 && a >= -m.maxDeceleration - 1e-3);
      // The rotational acceleration, away from curvature jumps (there are none in this chain).
      const double alpha = (now.rotational - before.rotational) / dt;
      CPPUNIT_ASSERT_MESSAGE("rotational acceleration " + std::to_string(alpha) + " at s=" + std::to_string(now.s),
                             std::abs(alpha) <= m.maxRotationalAcceleration * 1.01);
      fastest = std::max(fastest, now.velocity);
      before = now;
    }
    // The profile is not timid: the straight at the end reaches the top speed's neighbourhood.
    CPPUNIT_ASSERT(fastest > 0.9);
  }

  void predictionMatchesIntegratedDrive() {
    const TimedTrajectory timed(mixedChain(), MotionLimits{});
    // A robot that drives at the profile's speed for its arc length, in 0.1 mm steps.
    const double ds = 1e-4, length = timed.chain().length();
    double seconds = 0.0;
    for (double s = 0.0; s < length; s += ds) {
      const double step = std::min(ds, length - s);
      seconds += 2.0 * step / (timed.speedAt(s) + timed.speedAt(s + step));
    }
    CPPUNIT_ASSERT_DOUBLES_EQUAL(timed.duration(), seconds, 1e-3 * timed.duration());
    const rgnav::Pose2D end = timed.stateAt(timed.duration()).pose;
    CPPUNIT_ASSERT_DOUBLES_EQUAL(timed.chain().end().x, end.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(timed.chain().end().y, end.y, 1e-12);
  }

  void timeAndArcLengthInvert() {
    const TimedTrajectory timed(mixedChain(), MotionLimits{});
    for (double t = 0.0; t < timed.duration(); t += 0.37) {
      const ReferenceState state = timed.stateAt(t);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(t, timed.timeAt(state.s), 1e-6);
      CPPUNIT_ASSERT_DOUBLES_EQUAL(state.velocity, timed.speedAt(state.s), 1e-6);
    }
  }

  void turnOnTheSpotIsTimed() {
    // A quarter turn on an arc of 1 mm radius (1.6 mm long, shorter than a grid step): the
    // rotational acceleration and speed limits (pi/2) time it as a bang-bang turn of 2 s.
    TrajectoryChain spot;
    spot.append({{}, 0.001 * M_PI / 2.0, 1000.0, 0.0});
    const TimedTrajectory timed(spot, MotionLimits{});
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, timed.duration(), 0.02);
    CPPUNIT_ASSERT(std::abs(timed.stateAt(1.0).rotational) <= MotionLimits{}.maxRotationalVelocity + 1e-9);
  }

  void curvatureJumpsAreSlowed() {
    const MotionLimits m;
    // A straight into an arc of radius 1 m: the rotational speed steps by v at the joint.
    TrajectoryChain chain;
    chain.append({{}, 3.0, 0.0, 0.0});
    chain.append({chain.end(), 3.0, 1.0, 0.0});
    const TimedTrajectory timed(chain, m);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(m.maxRotationalAcceleration * 0.05, timed.speedAt(3.0), 1e-9);
    CPPUNIT_ASSERT(timed.speedAt(1.5) > 0.5);
    // A spot turn before a straight stops rotating (nearly) before it drives off.
    TrajectoryChain spot;
    spot.append({{}, 0.001 * M_PI / 2.0, 1000.0, 0.0});
    spot.append({spot.end(), 1.0, 0.0, 0.0});
    const TimedTrajectory spotTimed(spot, m);
    const double joint = spotTimed.timeAt(0.001 * M_PI / 2.0);
    CPPUNIT_ASSERT(std::abs(spotTimed.stateAt(joint - 1e-6).rotational) <= m.maxRotationalAcceleration * 0.05 + 1e-3);
  }

  void startSpeedsAreChecked() {
    TrajectoryChain tight;
    tight.append({{0.0, 0.0, 0.0}, 1.0, 4.0, 0.0});  // |kappa| v <= 1.57: v <= 0.39
    CPPUNIT_ASSERT_THROW(TimedTrajectory(tight, MotionLimits{}, 0.8), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_NO_THROW(TimedTrajectory(tight, MotionLimits{}, 0.35));
    TrajectoryChain shortStraight;
    shortStraight.append({{0.0, 0.0, 0.0}, 0.5, 0.0, 0.0});  // braking from 1 m/s needs 1 m
    CPPUNIT_ASSERT_THROW(TimedTrajectory(shortStraight, MotionLimits{}, 1.0), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_NO_THROW(TimedTrajectory(shortStraight, MotionLimits{}, 0.6));
    CPPUNIT_ASSERT_THROW(TimedTrajectory(TrajectoryChain{}, MotionLimits{}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(TimedTrajectory(shortStraight, MotionLimits{}, -0.1), rgnav::InvalidArgumentError);
  }

  void cruiseSpeedHoldsAfterBraking() {
    TrajectoryChain chain;
    chain.append({{0.0, 0.0, 0.0}, 4.0, 0.0, 0.0});
    // From 1 m/s, braking at 0.5 m/s^2 to 0.5 m/s takes 0.75 m (1 s); then 0.5 m/s until the stop.
    const TimedTrajectory timed(chain, MotionLimits{}, 1.0, 0.0, 0.5);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, timed.startSpeed(), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(std::sqrt(0.5), timed.speedAt(0.5), 1e-6);  // v^2 = 1 - 2 * 0.5 * 0.5
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.5, timed.speedAt(2.0), 1e-9);
    // 1 s down to 0.5 m/s, (4 - 0.75 - 0.25) m at 0.5 m/s, 1 s to the stop.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0 + 3.0 / 0.5 + 1.0, timed.duration(), 1e-3);
    CPPUNIT_ASSERT_THROW(TimedTrajectory(chain, MotionLimits{}, 0.0, 0.0, 0.0), rgnav::InvalidArgumentError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(TimedTrajectoryTest);
