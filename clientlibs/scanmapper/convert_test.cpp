// Round trips of the ScanMapper.idl conversions: a batch of corrected scans, pose updates and
// pose revisions.
#include <cppunit/extensions/HelperMacros.h>

#include "clientlibs/scanmapper/convert.h"

using namespace rgnav;

class ScanMapperConvertTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ScanMapperConvertTest);
  CPPUNIT_TEST(batchRoundTrip);
  CPPUNIT_TEST(poseUpdateRoundTrip);
  CPPUNIT_TEST(poseRevisionRoundTrip);
  CPPUNIT_TEST_SUITE_END();

 public:
  void batchRoundTrip() {
    CorrectedBatch batch;
    for (DataId id = 3; id <= 5; ++id) {
      LaserScan scan;
      scan.id = id;
      scan.stamp = 0.1 * double(id);
      scan.odometry = {double(id), 1.0, 0.2};
      scan.angleIncrement = 0.01;
      scan.maxRange = 80.0;
      scan.ranges = {1.0f, LaserScan::kNoReturn, 2.5f};
      batch.scans.push_back(
          CorrectedScan{scan, {double(id) + 0.01, 0.99, 0.21}, {double(id) - 0.02, 1.01, 0.19}, id % 2 == 1});
    }
    batch.latestId = 9;
    batch.revision = 4;
    batch.endOfData = true;
    const CorrectedBatch back = fromIdl(toIdl(batch));
    CPPUNIT_ASSERT(back.scans == batch.scans);
    CPPUNIT_ASSERT_EQUAL(batch.latestId, back.latestId);
    CPPUNIT_ASSERT_EQUAL(batch.revision, back.revision);
    CPPUNIT_ASSERT(back.endOfData);
  }
  void poseUpdateRoundTrip() {
    const PoseUpdate update{12, {1.5, -2.5, 3.0}};
    CPPUNIT_ASSERT(fromIdl(toIdl(update)) == update);
  }
  void poseRevisionRoundTrip() {
    const PoseRevisionInfo revision{7, 1234};
    CPPUNIT_ASSERT(fromIdl(toIdl(revision)) == revision);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(ScanMapperConvertTest);
