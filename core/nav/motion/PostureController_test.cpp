// Tests Kanayama's tracking law: the posture error is seen from the robot; a unicycle that starts
// off the reference (0.3 m aside, 0.4 rad askew) converges onto a reference moving along a
// straight and along a circle, with the Lyapunov function falling; commands keep to the limits;
// bad gains are rejected.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>

#include "core/common/Errors.h"
#include "core/nav/motion/PostureController.h"

using rgnav::MotionLimits;
using rgnav::Pose2D;
using rgnav::PostureController;
using rgnav::PostureGains;

namespace {

// Kanayama's Lyapunov function.
double lyapunov(const Pose2D& e, const PostureGains& g) {
  return e.x * e.x + e.y * e.y + 2.0 * (1.0 - std::cos(e.theta)) / g.ky;
}

// Drives a unicycle at 20 Hz (commands held for a tick, integrated finely) after a reference
// moving at (v, w) from the origin; returns the Lyapunov function every second.
std::vector<double> follow(double v, double w, const Pose2D& robotStart, double seconds) {
  const PostureGains gains;
  const PostureController controller(gains, MotionLimits{});
  Pose2D robot = robotStart, reference;
  std::vector<double> values;
  const int ticks = static_cast<int>(seconds / 0.05);
  for (int k = 0; k < ticks; ++k) {
    if (k % 20 == 0) values.push_back(lyapunov(rgnav::postureError(robot, reference), gains));
    const rgnav::VelocityCommand c = controller.command(robot, reference, v, w);
    for (int i = 0; i < 50; ++i) {
      const double h = 0.001;
      robot = {robot.x + h * c.translational * std::cos(robot.theta),
               robot.y + h * c.translational * std::sin(robot.theta), robot.theta + h * c.rotational};
      reference = {reference.x + h * v * std::cos(reference.theta),
                   reference.y + h * v * std::sin(reference.theta), reference.theta + h * w};
    }
  }
  values.push_back(lyapunov(rgnav::postureError(robot, reference), gains));
  return values;
}

}  // namespace

class PostureControllerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PostureControllerTest);
  CPPUNIT_TEST(errorIsInRobotFrame);
  CPPUNIT_TEST(convergesOnStraight);
  CPPUNIT_TEST(convergesOnCircle);
  CPPUNIT_TEST(commandsKeepToLimits);
  CPPUNIT_TEST(badGainsAreRejected);
  CPPUNIT_TEST_SUITE_END();

 public:
  void errorIsInRobotFrame() {
    const Pose2D e = rgnav::postureError({1.0, 1.0, M_PI / 2.0}, {1.0, 2.0, M_PI});
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, e.x, 1e-12);  // ahead of the robot
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, e.y, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI / 2.0, e.theta, 1e-12);
  }

  void convergesOnStraight() {
    const std::vector<double> v = follow(0.5, 0.0, {-0.2, 0.3, -0.4}, 10.0);
    CPPUNIT_ASSERT(v.back() < 1e-4 * v.front());
    for (std::size_t i = 1; i < v.size(); ++i) CPPUNIT_ASSERT(v[i] <= v[i - 1] * 1.01);
  }

  void convergesOnCircle() {
    const std::vector<double> v = follow(0.6, 0.5, {0.1, -0.3, 0.4}, 10.0);
    CPPUNIT_ASSERT(v.back() < 1e-4 * v.front());
  }

  void commandsKeepToLimits() {
    const MotionLimits m;
    const PostureController controller(PostureGains{}, m);
    const rgnav::VelocityCommand c = controller.command({0.0, 0.0, 0.0}, {5.0, 3.0, 2.0}, 1.0, 1.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(m.maxVelocity, c.translational, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(m.maxRotationalVelocity, c.rotational, 1e-12);
  }

  void badGainsAreRejected() {
    PostureGains g;
    g.ky = 0.0;
    CPPUNIT_ASSERT_THROW(PostureController(g, MotionLimits{}), rgnav::ConfigError);
    MotionLimits m;
    m.maxLateralAcceleration = -1.0;
    CPPUNIT_ASSERT_THROW(PostureController(PostureGains{}, m), rgnav::ConfigError);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PostureControllerTest);
