// Tests the pose algebra: composition, inverse, relative poses and angle wrapping.
#include <cppunit/extensions/HelperMacros.h>

#include "core/common/Pose2D.h"

using rgnav::Pose2D;

class Pose2DTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(Pose2DTest);
  CPPUNIT_TEST(composeWithInverseIsIdentity);
  CPPUNIT_TEST(betweenRecoversRelativePose);
  CPPUNIT_TEST(normalizeWrapsIntoHalfOpenInterval);
  CPPUNIT_TEST_SUITE_END();

 public:
  void composeWithInverseIsIdentity() {
    const Pose2D a{1.5, -2.0, 2.8};
    const Pose2D id = rgnav::compose(a, rgnav::inverse(a));
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, id.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, id.y, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(0.0, id.theta, 1e-12);
  }
  void betweenRecoversRelativePose() {
    const Pose2D a{1.0, 2.0, M_PI / 2};
    const Pose2D rel{0.5, 0.25, -0.3};
    const Pose2D b = rgnav::compose(a, rel);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(1.0 - 0.25, b.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(2.5, b.y, 1e-12);
    const Pose2D back = rgnav::between(a, b);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(rel.x, back.x, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(rel.y, back.y, 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(rel.theta, back.theta, 1e-12);
  }
  void normalizeWrapsIntoHalfOpenInterval() {
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI, rgnav::normalizeAngle(-M_PI), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(M_PI, rgnav::normalizeAngle(M_PI), 1e-12);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(-0.5, rgnav::normalizeAngle(-0.5 + 4 * M_PI), 1e-12);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(Pose2DTest);
