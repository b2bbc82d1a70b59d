// integration_playback_test: the Intel log served by the real set (omniNames + watchdog +
// rgnav-carmen-playback --speed max), read through LaserClient and BaseClient: every scan and
// odometry reading in order, typed errors for bad IDs and counts, the server's batch cap, a
// small buffer dropping old scans, interpolated odometry, and the module's status.
#include <cppunit/extensions/HelperMacros.h>

#include <limits>
#include <variant>

#include "clientlibs/base/BaseClient.h"
#include "core/logs/OpenLog.h"
#include "tests/integration/IntegrationHelpers.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

// One playback module of the Intel log with extra options, started and running.
struct PlaybackSet {
  explicit PlaybackSet(const std::vector<std::string>& extra = {})
      : cluster({{"LogPlayback", playbackCommand(intelLog(), extra), {"Laser", "Base"}}}) {
    cluster.start();
  }
  TestCluster cluster;
};

// The next scan the log reader yields, skipping odometry.
LaserScan nextScan(LogSource& log) {
  while (auto record = log.next())
    if (auto* scan = std::get_if<LaserScan>(&*record)) return std::move(*scan);
  CPPUNIT_FAIL("the log has fewer scans than were served");
  return {};
}

}  // namespace

class PlaybackIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PlaybackIntegrationTest);
  CPPUNIT_TEST(testEveryScanInOrder);
  CPPUNIT_TEST(testBadScanRequestsGetTypedErrors);
  CPPUNIT_TEST(testServerCapsLargeBatches);
  CPPUNIT_TEST(testSmallBufferDropsOldestScans);
  CPPUNIT_TEST(testOdometryReadingsAndInterpolation);
  CPPUNIT_TEST(testStatusShowsCountersAndWatchdogPid);
  CPPUNIT_TEST_SUITE_END();

 public:
  void testEveryScanInOrder() {
    PlaybackSet set;
    LaserClient laser(set.cluster.clientSettings());
    const std::vector<LaserScan> scans = readAllScans(laser, 100);
    CPPUNIT_ASSERT_EQUAL(kIntelScans, scans.size());
    // The same scans as the log reader yields here, in log order (stamps in this log do step
    // back now and then, so the order is checked against the file, not by stamp).
    auto log = openLog(intelLog());
    for (std::size_t i = 0; i < scans.size(); ++i) {
      CPPUNIT_ASSERT_EQUAL(DataId(i + 1), scans[i].id);
      const LaserScan expected = nextScan(*log);
      CPPUNIT_ASSERT_EQUAL(expected.stamp, scans[i].stamp);
      CPPUNIT_ASSERT_EQUAL(expected.ranges.size(), scans[i].ranges.size());
      CPPUNIT_ASSERT_EQUAL(expected.odometry.x, scans[i].odometry.x);
    }
    CPPUNIT_ASSERT_EQUAL(DataId(kIntelScans), laser.latestId());
    const LaserScan last = laser.scan(kIntelScans);
    CPPUNIT_ASSERT_EQUAL(scans.back().stamp, last.stamp);
    CPPUNIT_ASSERT_EQUAL(scans.back().ranges.size(), last.ranges.size());
  }

  void testBadScanRequestsGetTypedErrors() {
    PlaybackSet set;
    LaserClient laser(set.cluster.clientSettings());
    CPPUNIT_ASSERT_EQUAL(DataId(1), laser.scan(1).id);
    CPPUNIT_ASSERT_THROW(laser.scan(0), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(laser.scan(5000), NotAvailableError);
    CPPUNIT_ASSERT_THROW(laser.scan(std::numeric_limits<DataId>::max()), NotAvailableError);
    CPPUNIT_ASSERT_THROW(laser.scansSince(0, 0), InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(laser.scansSince(10, 0), InvalidArgumentError);
    // An over-long consumer name is refused; no error reaches the client as CORBA::UNKNOWN.
    TypedConnection<RGNav::Laser> raw("Laser", set.cluster.clientSettings());
    CPPUNIT_ASSERT_THROW(raw.call("scansSince", [](RGNav::Laser_ptr l) {
      const std::string name(100000, 'c');
      RGNav::ScanBatch_var batch = l->scansSince(0, 1, name.c_str());
    }), BadArgumentError);
    // The server still serves normally after the errors.
    CPPUNIT_ASSERT_EQUAL(kIntelScans, readAllScans(laser, 200).size());
  }

  void testServerCapsLargeBatches() {
    PlaybackSet set({"--max-batch", "64"});
    LaserClient laser(set.cluster.clientSettings());
    const auto scans = laser.scansSince(0, 100000);
    CPPUNIT_ASSERT_EQUAL(std::size_t{64}, scans.records.size());
    CPPUNIT_ASSERT_EQUAL(DataId(1), scans.records.front().id);
    CPPUNIT_ASSERT_EQUAL(DataId(64), scans.records.back().id);
    BaseClient base(set.cluster.clientSettings());
    CPPUNIT_ASSERT_EQUAL(std::size_t{64}, base.odometrySince(0, 100000).records.size());
  }

  void testSmallBufferDropsOldestScans() {
    PlaybackSet set({"--buffer", "100"});
    LaserClient laser(set.cluster.clientSettings());
    CPPUNIT_ASSERT_EQUAL(kIntelScans, readAllScans(laser, 50).size());
    CPPUNIT_ASSERT_EQUAL(DataId(811), laser.oldestId());
    CPPUNIT_ASSERT_THROW(laser.scan(1), NotAvailableError);
    CPPUNIT_ASSERT_THROW(laser.scan(810), NotAvailableError);
    CPPUNIT_ASSERT_EQUAL(DataId(811), laser.scan(811).id);
    // "Everything after 0" starts at the oldest scan still held.
    const auto held = laser.scansSince(0, 500);
    CPPUNIT_ASSERT_EQUAL(std::size_t{100}, held.records.size());
    CPPUNIT_ASSERT_EQUAL(DataId(811), held.records.front().id);
    CPPUNIT_ASSERT_EQUAL(DataId(811), held.oldestId);
  }

  void testOdometryReadingsAndInterpolation() {
    PlaybackSet set;
    BaseClient base(set.cluster.clientSettings());
    std::vector<OdometryReading> readings;
    for (int call = 0; call < 1000; ++call) {
      auto batch = base.odometrySince(readings.empty() ? 0 : readings.back().id, 500);
      if (batch.records.empty() && batch.endOfData) break;
      readings.insert(readings.end(), batch.records.begin(), batch.records.end());
    }
    CPPUNIT_ASSERT_EQUAL(kIntelOdometry, readings.size());
    for (std::size_t i = 0; i < readings.size(); ++i) CPPUNIT_ASSERT_EQUAL(DataId(i + 1), readings[i].id);
    CPPUNIT_ASSERT_EQUAL(DataId(kIntelOdometry), base.latestOdometryId());

    // Half way between two readings in the middle of the log (a pair no later pair brackets).
    const std::size_t i = pairToInterpolate(readings);
    const OdometryReading& a = readings[i];
    const OdometryReading& b = readings[i + 1];
    const OdometryReading at = base.odometryAt((a.stamp + b.stamp) / 2);
    CPPUNIT_ASSERT_DOUBLES_EQUAL((a.pose.x + b.pose.x) / 2, at.pose.x, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL((a.pose.y + b.pose.y) / 2, at.pose.y, 1e-6);
    CPPUNIT_ASSERT_DOUBLES_EQUAL((a.stamp + b.stamp) / 2, at.stamp, 1e-9);

    CPPUNIT_ASSERT_THROW(base.odometryAt(readings.back().stamp + 1e6), NotAvailableError);
    CPPUNIT_ASSERT_THROW(base.odometryAt(-1e6), NotAvailableError);
    CPPUNIT_ASSERT_THROW(base.setVelocity(0.2, 0.0), NotSupportedError);
  }

  void testStatusShowsCountersAndWatchdogPid() {
    PlaybackSet set;
    LaserClient laser(set.cluster.clientSettings());
    CPPUNIT_ASSERT_EQUAL(kIntelScans, readAllScans(laser, 100).size());
    const ModuleStatusInfo status = laser.status();
    CPPUNIT_ASSERT_EQUAL(std::string("LogPlayback"), status.name);
    CPPUNIT_ASSERT(status.state == ModuleRunState::Running);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{kIntelScans}, status.counters.at("scans_served"));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{kIntelScans}, status.counters.at("log_scans"));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{kIntelOdometry}, status.counters.at("log_odometry"));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{0}, status.counters.at("log_malformed_lines"));
    CPPUNIT_ASSERT_EQUAL(set.cluster.describe("LogPlayback").pid, std::int64_t{status.pid});
  }

 private:
  // A pair (i, i+1) past the middle with rising stamps and moving x, bracketing a stamp that no
  // later pair brackets (the server searches from the newest reading back).
  static std::size_t pairToInterpolate(const std::vector<OdometryReading>& r) {
    for (std::size_t i = r.size() / 2; i + 1 < r.size(); ++i) {
      const double mid = (r[i].stamp + r[i + 1].stamp) / 2;
      if (!(r[i].stamp < r[i + 1].stamp && r[i].pose.x != r[i + 1].pose.x)) continue;
      bool laterBrackets = false;
      for (std::size_t k = i + 1; k + 1 < r.size() && !laterBrackets; ++k)
        laterBrackets = r[k].stamp <= mid && mid <= r[k + 1].stamp;
      if (!laterBrackets) return i;
    }
    CPPUNIT_FAIL("no odometry pair to interpolate between");
    return 0;
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PlaybackIntegrationTest);
