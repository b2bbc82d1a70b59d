// Round trips of the GroundTruth.idl door line and person conversions.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/groundtruth/convert.h"

using namespace rgnav;

class GroundTruthConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GroundTruthConvertTest);
  CPPUNIT_TEST(doorLineRoundTrip);
  CPPUNIT_TEST(personRoundTrip);
  CPPUNIT_TEST_SUITE_END();

 public:
  void doorLineRoundTrip() {
    const DoorLine door{{1.5, -2.0}, {2.4, -2.0}, 3, -1};
    const DoorLine back = fromIdl(toIdl(door));
    CPPUNIT_ASSERT_EQUAL(door.a.x, back.a.x);
    CPPUNIT_ASSERT_EQUAL(door.a.y, back.a.y);
    CPPUNIT_ASSERT_EQUAL(door.b.x, back.b.x);
    CPPUNIT_ASSERT_EQUAL(door.b.y, back.b.y);
    CPPUNIT_ASSERT_EQUAL(door.roomA, back.roomA);
    CPPUNIT_ASSERT_EQUAL(door.roomB, back.roomB);
  }

  void personRoundTrip() {
    const Person person{{1.5, -2.0}, {0.3, -0.9}, 0.25};
    const Person back = fromIdl(toIdl(person));
    CPPUNIT_ASSERT_EQUAL(person.position.x, back.position.x);
    CPPUNIT_ASSERT_EQUAL(person.position.y, back.position.y);
    CPPUNIT_ASSERT_EQUAL(person.velocity.x, back.velocity.x);
    CPPUNIT_ASSERT_EQUAL(person.velocity.y, back.velocity.y);
    CPPUNIT_ASSERT_EQUAL(person.radius, back.radius);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(GroundTruthConvertTest);
