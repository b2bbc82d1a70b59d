// The ScanMapper module through the real server set: every scan of the Intel keyframes gets a
// corrected pose, typed errors for bad IDs, odomToMap by scan ID, and a restart by the operator
// resumes from the checkpoint with the very same poses.
#include <cppunit/extensions/HelperMacros.h>

#include <chrono>
#include <cmath>
#include <filesystem>

#include "clientlibs/scanmapper/ScanMapperClient.h"
#include "tests/integration/IntegrationHelpers.h"

using namespace rgnav;
using namespace rgnav::testing;

class ScanMapperIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ScanMapperIntegrationTest);
  CPPUNIT_TEST(testCorrectedScansErrorsAndResume);
  CPPUNIT_TEST_SUITE_END();

 public:
  void testCorrectedScansErrorsAndResume() {
    const std::string derived = TestCluster::shared("data/laser/derived/");
    TestCluster cluster({{"LogPlayback",
                          playbackCommand(derived + "xiaofeng-intel_gfs.json.xz",
                                          {"--corrected", derived + "xiaofeng-intel_corrected_log.json.xz"}),
                          {"Laser", "Base"}},
                         {"ScanMapper",
                          {TestCluster::program("rgnav-scanmapper"), "--config", TestCluster::moduleConfig("scanmapper")},
                          {"ScanMapper"},
                          {"LogPlayback"}}},
                        kFastBackoff);
    cluster.start();
    ScanMapperClient mapper(cluster.clientSettings());
    DataId last = 0;
    std::size_t keyframes = 0;
    waitUntil(
        [&] {
          const CorrectedBatch batch = mapper.correctedSince(last, 100);
          for (const CorrectedScan& s : batch.scans) {
            CPPUNIT_ASSERT_EQUAL(last + 1, s.scan.id);
            last = s.scan.id;
            keyframes += s.keyframe;
          }
          return batch.scans.empty() && batch.endOfData;
        },
        "the corrected scans to end", std::chrono::seconds(120));
    CPPUNIT_ASSERT_EQUAL(DataId(910), last);
    CPPUNIT_ASSERT(keyframes > 100);

    CPPUNIT_ASSERT_THROW(mapper.correctedPose(0), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(mapper.correctedPose(100000), NotAvailableError);
    CPPUNIT_ASSERT_THROW(mapper.poses(10, 5), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(mapper.poses(5000, 6000), NotAvailableError);

    // The odometry pose of scan 5, placed with scan 5's correction, is scan 5's corrected pose.
    LaserClient laser(cluster.clientSettings());
    const Pose2D mapped = mapper.odomToMap(5, laser.scan(5).odometry);
    const Pose2D corrected = mapper.correctedPose(5);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(corrected.x, mapped.x, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(corrected.y, mapped.y, 1e-6);

    const std::vector<PoseUpdate> before = mapper.poses(1, 910);
    CPPUNIT_ASSERT(std::filesystem::exists(cluster.dir() + "/run/state/ScanMapper/slam.state"));
    const auto old = cluster.describe("ScanMapper");
    cluster.watchdog().restartModule("ScanMapper");
    cluster.waitFor("ScanMapper", runningAgainAfter(old.pid), "restarted");
    const std::vector<PoseUpdate> after = mapper.poses(1, 910);
    CPPUNIT_ASSERT(before == after);
    CPPUNIT_ASSERT_EQUAL(DataId(910), mapper.latestCorrectedId());
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(ScanMapperIntegrationTest);
