// Tests the keyframe filter of thesis 5.2: a scan is kept after enough distance or enough turn.
#include <cppunit/extensions/HelperMacros.h>

#include "core/slam/KeyframeFilter.h"

class KeyframeFilterTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(KeyframeFilterTest);
  CPPUNIT_TEST(distanceOrAngleMakesAKeyframe);
  CPPUNIT_TEST(measuredInTheLastKeyframesFrame);
  CPPUNIT_TEST_SUITE_END();

 public:
  void distanceOrAngleMakesAKeyframe() {
    const rgnav::KeyframeFilterConfig config{0.5, 0.2};
    const rgnav::Pose2D last{1.0, 2.0, 0.3};
    CPPUNIT_ASSERT(!rgnav::isKeyframe(last, last, config));
    CPPUNIT_ASSERT(!rgnav::isKeyframe(last, rgnav::compose(last, {0.3, 0.3, 0.1}), config));
    CPPUNIT_ASSERT(rgnav::isKeyframe(last, rgnav::compose(last, {0.4, 0.3, 0.0}), config));   // 0.5 m
    CPPUNIT_ASSERT(rgnav::isKeyframe(last, rgnav::compose(last, {-0.5, 0.0, 0.0}), config));  // backwards
    CPPUNIT_ASSERT(rgnav::isKeyframe(last, rgnav::compose(last, {0.0, 0.0, -0.2}), config));  // turning on the spot
    CPPUNIT_ASSERT(!rgnav::isKeyframe(last, rgnav::compose(last, {0.0, 0.0, 0.19}), config));
  }
  void measuredInTheLastKeyframesFrame() {
    const rgnav::KeyframeFilterConfig config{0.5, 0.2};
    // Across the angle wrap: 3.1 to -3.1 rad is a turn of 0.083 rad, not 6.2.
    CPPUNIT_ASSERT(!rgnav::isKeyframe({0, 0, 3.1}, {0, 0, -3.1}, config));
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(KeyframeFilterTest);
