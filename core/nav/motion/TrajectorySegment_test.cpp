// Tests the trajectory primitives: end poses of straights and arcs against their closed forms,
// clothoids against the tabulated Fresnel integrals and against a fine midpoint integration of
// the heading, clamping of the arc length, and the rejection of invalid segments.
#include <cppunit/extensions/HelperMacros.h>

#include <cmath>
#include <limits>

#include "core/common/Errors.h"
#include "core/nav/motion/TrajectorySegment.h"

using rgnav::Pose2D;
using rgnav::SegmentKind;
using rgnav::TrajectorySegment;

namespace {

// The pose after `length` by the midpoint rule on a million steps of the heading.
Pose2D integrated(const TrajectorySegment& seg) {
  const int steps = 1000000;
  const double h = seg.length / steps;
  double x = seg.start.x, y = seg.start.y;
  for (int i = 0; i < steps; ++i) {
    const double u = (i + 0.5) * h;
    const double theta = seg.start.theta + seg.curvature * u + 0.5 * seg.sharpness * u * u;
    x += h * std::cos(theta);
    y += h * std::sin(theta);
  }
  return {x, y, rgnav::normalizeAngle(seg.start.theta + seg.curvature * seg.length +
                                      0.5 * seg.sharpness * seg.length * seg.length)};
}

void assertPose(const Pose2D& expected, const Pose2D& actual, double tolerance) {
  CPPUNIT_ASSERT_DOUBLES_EQUAL(expected.x, actual.x, tolerance);
  CPPUNIT_ASSERT_DOUBLES_EQUAL(expected.y, actual.y, tolerance);
  CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, rgnav::normalizeAngle(expected.theta - actual.theta), 1e-12);
}

}  // namespace

class TrajectorySegmentTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(TrajectorySegmentTest);
  CPPUNIT_TEST(straightEndsOnItsLine);
  CPPUNIT_TEST(arcEndsOnItsCircle);
  CPPUNIT_TEST(clothoidMatchesFresnelTable);
  CPPUNIT_TEST(clothoidsMatchFineIntegration);
  CPPUNIT_TEST(arcLengthIsClamped);
  CPPUNIT_TEST(kindFollowsParameters);
  CPPUNIT_TEST(invalidSegmentsAreRejected);
  CPPUNIT_TEST_SUITE_END();

 public:
  void straightEndsOnItsLine() {
    const TrajectorySegment seg{{1.0, 2.0, 0.5}, 3.0, 0.0, 0.0};
    assertPose({1.0 + 3.0 * std::cos(0.5), 2.0 + 3.0 * std::sin(0.5), 0.5}, seg.end(), 1e-12);
  }

  void arcEndsOnItsCircle() {
    // A quarter circle of radius 2 to the left, and three quarters to the right.
    const TrajectorySegment left{{0.0, 0.0, 0.0}, M_PI, 0.5, 0.0};
    assertPose({2.0, 2.0, M_PI / 2.0}, left.end(), 1e-12);
    const TrajectorySegment right{{0.0, 0.0, M_PI / 2.0}, 1.5 * M_PI, -1.0, 0.0};
    assertPose({1.0, -1.0, M_PI}, right.end(), 1e-12);
    // Any point lies on the circle about (1, 0).
    const Pose2D mid = right.poseAt(1.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0, std::hypot(mid.x - 1.0, mid.y), 1e-12);
  }

  void clothoidMatchesFresnelTable() {
    // theta = pi s^2 / 2: x(1) = C(1), y(1) = S(1) (Abramowitz & Stegun, table 7.7).
    const TrajectorySegment seg{{0.0, 0.0, 0.0}, 1.0, 0.0, M_PI};
    assertPose({0.7798934003768228, 0.4382591473903548, M_PI / 2.0}, seg.end(), 1e-12);
    // C(2) = 0.4882534060753408, S(2) = 0.3434156783636982 (theta = 2 pi at s = 2).
    const TrajectorySegment longer{{0.0, 0.0, 0.0}, 2.0, 0.0, M_PI};
    assertPose({0.4882534060753408, 0.3434156783636982, 0.0}, longer.end(), 1e-12);
  }

  void clothoidsMatchFineIntegration() {
    const TrajectorySegment cases[] = {
        {{0.3, -1.2, 2.0}, 2.5, 0.4, -0.9},  // curvature changes sign
        {{-4.0, 7.0, -2.9}, 12.0, -0.1, 0.05},
        {{0.0, 0.0, 0.0}, 0.7, 2.0, 3.0},
    };
    for (const TrajectorySegment& seg : cases) assertPose(integrated(seg), seg.end(), 1e-9);
  }

  void arcLengthIsClamped() {
    const TrajectorySegment seg{{0.0, 0.0, 0.0}, 1.0, 0.2, 0.3};
    CPPUNIT_ASSERT(seg.poseAt(-1.0) == seg.start);
    CPPUNIT_ASSERT(seg.poseAt(5.0) == seg.end());
  }

  void kindFollowsParameters() {
    CPPUNIT_ASSERT(TrajectorySegment({{}, 1.0, 0.0, 0.0}).kind() == SegmentKind::Straight);
    CPPUNIT_ASSERT(TrajectorySegment({{}, 1.0, 0.5, 0.0}).kind() == SegmentKind::Arc);
    CPPUNIT_ASSERT(TrajectorySegment({{}, 1.0, 0.0, 0.5}).kind() == SegmentKind::Clothoid);
  }

  void invalidSegmentsAreRejected() {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CPPUNIT_ASSERT_THROW(validate(TrajectorySegment{{}, 0.0, 0.0, 0.0}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(validate(TrajectorySegment{{}, -1.0, 0.0, 0.0}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(validate(TrajectorySegment{{}, 1.0, nan, 0.0}), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(validate(TrajectorySegment{{nan, 0.0, 0.0}, 1.0, 0.0, 0.0}),
                         rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_NO_THROW(validate(TrajectorySegment{{}, 1.0, 0.0, 0.0}));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(TrajectorySegmentTest);
