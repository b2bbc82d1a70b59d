// Tests the thesis' min angle and distance functions between line segments (3.1).
#include "core/objects/SegmentRelations.h"

#include <cppunit/extensions/HelperMacros.h>

using Eigen::Vector2d;
using rgnav::minAngle;
using rgnav::segmentDistance;
using rgnav::segmentFromEndpoints;

namespace {
constexpr double kDeg = M_PI / 180.0;
rgnav::LineSegment seg(double x0, double y0, double x1, double y1) {
  return segmentFromEndpoints(1, {x0, y0}, {x1, y1});
}
}  // namespace

class SegmentRelationsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SegmentRelationsTest);
  CPPUNIT_TEST(minAngleIsSmallerIntersectionAngle);
  CPPUNIT_TEST(distanceIsZeroForRealIntersection);
  CPPUNIT_TEST(openCornerDistanceIsTheExtensionNeeded);
  CPPUNIT_TEST(distanceUsesEndpointsOtherwise);
  CPPUNIT_TEST(lineIntersection);
  CPPUNIT_TEST_SUITE_END();

 public:
  void minAngleIsSmallerIntersectionAngle() {
    const auto x = seg(0, 0, 1, 0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(90 * kDeg, minAngle(x, seg(5, 5, 5, 6)), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(30 * kDeg, minAngle(x, seg(0, 0, std::cos(30 * kDeg), std::sin(30 * kDeg))), 1e-12);
    // 150 and 30 degrees give the same lines' smaller angle; the direction does not matter.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(30 * kDeg, minAngle(x, seg(0, 0, std::cos(150 * kDeg), std::sin(150 * kDeg))), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(30 * kDeg,
                                 minAngle(seg(1, 0, 0, 0), seg(0, 0, std::cos(30 * kDeg), std::sin(30 * kDeg))), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, minAngle(x, seg(3, 2, 7, 2)), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(minAngle(x, seg(0, 0, 2, 1)), minAngle(seg(0, 0, 2, 1), x), 1e-15);
  }

  void distanceIsZeroForRealIntersection() {
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, segmentDistance(seg(0, 0, 2, 0), seg(1, -1, 1, 1)), 1e-12);  // X
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, segmentDistance(seg(0, 0, 2, 0), seg(1, 0, 1, 1)), 1e-12);   // T
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, segmentDistance(seg(0, 0, 2, 0), seg(2, 0, 2, 1)), 1e-12);   // L
  }

  void openCornerDistanceIsTheExtensionNeeded() {
    // Both segments end 0.1 short of their common corner (0, 0): the virtual intersection is
    // 0.1 from each, the end points are 0.141 apart.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.1, segmentDistance(seg(0.1, 0, 1, 0), seg(0, 0.1, 0, 1)), 1e-12);
    // One reaches the corner, the other ends 0.15 short: 0.15.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.15, segmentDistance(seg(0, 0, 1, 0), seg(0, 0.15, 0, 1)), 1e-12);
    // Uneven: 0.05 and 0.12 short: the larger extension, 0.12 (end points are 0.13 apart).
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.12, segmentDistance(seg(0.05, 0, 1, 0), seg(0, 0.12, 0, 1)), 1e-12);
  }

  void distanceUsesEndpointsOtherwise() {
    // Parallel, side by side: the distance of the lines.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.5, segmentDistance(seg(0, 0, 2, 0), seg(0.5, 0.5, 1.5, 0.5)), 1e-12);
    // Collinear with a gap.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.3, segmentDistance(seg(0, 0, 1, 0), seg(1.3, 0, 2, 0)), 1e-12);
    // Perpendicular, the virtual intersection on one segment but 2 m from the other.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.0, segmentDistance(seg(0, 0, 1, 0), seg(0.5, 2, 0.5, 3)), 1e-12);
    // Nearly parallel lines meeting far away: the end points decide.
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.3, segmentDistance(seg(0, 0, 1, 0), seg(0, 0.3, 1, 0.31)), 1e-12);
    // Symmetric.
    const auto a = seg(0.2, 0.1, 1, 0.7), b = seg(-1, 2, 0.3, 0.9);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(segmentDistance(a, b), segmentDistance(b, a), 1e-12);
  }

  void lineIntersection() {
    const auto x = rgnav::lineIntersection(seg(0, 0, 1, 0), seg(3, 1, 3, 2));
    CPPUNIT_ASSERT(x && (*x - Vector2d(3, 0)).norm() < 1e-12);
    CPPUNIT_ASSERT(!rgnav::lineIntersection(seg(0, 0, 1, 0), seg(0, 1, 5, 1)));
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(SegmentRelationsTest);
