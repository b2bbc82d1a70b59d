// Round trip of a whole odometry batch through Base.idl types.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/base/convert.h"

using namespace rgnav;

class BaseConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(BaseConvertTest);
  CPPUNIT_TEST(batchRoundTrip);
  CPPUNIT_TEST_SUITE_END();

 public:
  void batchRoundTrip() {
    DataBatch<OdometryReading> batch;
    for (DataId id = 1; id <= 4; ++id)
      batch.records.push_back(OdometryReading{id, 0.5 * double(id), {double(id), -1.0, 0.1}, 0.3, -0.2});
    batch.oldestId = 1;
    batch.latestId = 4;
    const auto back = fromIdl(toIdl(batch));
    CPPUNIT_ASSERT(back.records == batch.records);
    CPPUNIT_ASSERT_EQUAL(batch.latestId, back.latestId);
    CPPUNIT_ASSERT(!back.endOfData);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(BaseConvertTest);
