// Round trip of the GroundTruth.idl door line conversion.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/groundtruth/convert.h"

using namespace rgnav;

class GroundTruthConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(GroundTruthConvertTest);
  CPPUNIT_TEST(doorLineRoundTrip);
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
};
CPPUNIT_TEST_SUITE_REGISTRATION(GroundTruthConvertTest);
