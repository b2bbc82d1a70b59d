// Round trip of a whole scan batch through Laser.idl types.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/laser/convert.h"

using namespace rgnav;

class LaserConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LaserConvertTest);
  CPPUNIT_TEST(batchRoundTrip);
  CPPUNIT_TEST_SUITE_END();

 public:
  void batchRoundTrip() {
    DataBatch<LaserScan> batch;
    for (DataId id = 5; id <= 7; ++id) {
      LaserScan s;
      s.id = id;
      s.stamp = 0.25 * double(id);
      s.angleIncrement = 0.01;
      s.maxRange = 80;
      s.ranges = {1.0f, 2.0f, float(id), LaserScan::kNoReturn};
      batch.records.push_back(s);
    }
    batch.oldestId = 1;
    batch.latestId = 9;
    batch.endOfData = true;
    const auto back = fromIdl(toIdl(batch));
    CPPUNIT_ASSERT(back.records == batch.records);
    CPPUNIT_ASSERT_EQUAL(batch.oldestId, back.oldestId);
    CPPUNIT_ASSERT_EQUAL(batch.latestId, back.latestId);
    CPPUNIT_ASSERT(back.endOfData);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(LaserConvertTest);
