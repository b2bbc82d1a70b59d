// Tests the release rules of LogPlayback on a small in-memory log and on the real Intel log.
#include <cppunit/extensions/HelperMacros.h>

#include <cstdlib>
#include <vector>

#include "core/logs/OpenLog.h"
#include "core/playback/LogPlayback.h"

using namespace rgnav;

namespace {

// Ten scans stamped 0..9 s with an odometry reading before each.
class TenSecondLog : public LogSource {
 public:
  TenSecondLog() {
    for (DataId id = 1; id <= 10; ++id) {
      records_.push_back(OdometryReading{id, double(id - 1), {double(id), 0, 0}, 1.0, 0.0});
      LaserScan scan;
      scan.id = id;
      scan.stamp = double(id - 1) + 0.5;
      scan.ranges = {1.0f};
      records_.push_back(scan);
    }
  }
  std::optional<LogRecord> next() override {
    if (at_ == records_.size()) return std::nullopt;
    return records_[at_++];
  }
  const LogStats& stats() const override { return stats_; }

 private:
  std::vector<LogRecord> records_;
  std::size_t at_ = 0;
  LogStats stats_;
};

std::string sharedPath(const std::string& rel) {
  const char* shared = std::getenv("RGNAV_SHARED");
  return std::string(shared ? shared : "../shared") + "/" + rel;
}

}  // namespace

class LogPlaybackTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LogPlaybackTest);
  CPPUNIT_TEST(realTimeReleasesByWallClock);
  CPPUNIT_TEST(scaledRealTimeReleasesFaster);
  CPPUNIT_TEST(asFastReleasesWhatConsumersAsk);
  CPPUNIT_TEST(consumersAreBoundedAndForgotten);
  CPPUNIT_TEST(odometryIsInterpolatedAtStamps);
  CPPUNIT_TEST(smallBufferDropsOldScans);
  CPPUNIT_TEST(slowestActiveConsumerPacesTheReplay);
  CPPUNIT_TEST(replaysTheWholeIntelLogInOrder);
  CPPUNIT_TEST_SUITE_END();

 public:
  void realTimeReleasesByWallClock() {
    LogPlayback playback(std::make_unique<TenSecondLog>(), parseReplayMode("realtime"), 100);
    CPPUNIT_ASSERT_EQUAL(DataId(0), playback.latestScanId(0.4));
    CPPUNIT_ASSERT_EQUAL(DataId(1), playback.latestScanId(0.5));
    CPPUNIT_ASSERT_EQUAL(DataId(3), playback.latestScanId(2.7));
    const auto batch = playback.scansSince(0, 100, 2.7);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), batch.records.size());
    CPPUNIT_ASSERT(!batch.endOfData);
    CPPUNIT_ASSERT(playback.scansSince(0, 100, 100.0).endOfData);
  }
  void scaledRealTimeReleasesFaster() {
    LogPlayback playback(std::make_unique<TenSecondLog>(), parseReplayMode("x10"), 100);
    CPPUNIT_ASSERT_EQUAL(DataId(5), playback.latestScanId(0.46));
  }
  void asFastReleasesWhatConsumersAsk() {
    LogPlayback playback(std::make_unique<TenSecondLog>(), parseReplayMode("max"), 100);
    const auto first = playback.scansSince(0, 4, 0.0);
    CPPUNIT_ASSERT_EQUAL(std::size_t(4), first.records.size());
    CPPUNIT_ASSERT_EQUAL(DataId(4), first.latestId);
    const auto rest = playback.scansSince(4, 100, 0.0);
    CPPUNIT_ASSERT_EQUAL(std::size_t(6), rest.records.size());
    CPPUNIT_ASSERT(rest.endOfData);
    CPPUNIT_ASSERT_EQUAL(DataId(10), playback.latestOdometryId(0.0));
  }
  void odometryIsInterpolatedAtStamps() {
    LogPlayback playback(std::make_unique<TenSecondLog>(), parseReplayMode("max"), 100);
    const auto odo = playback.odometryAt(2.25, 0.0);
    CPPUNIT_ASSERT_DOUBLES_EQUAL(3.25, odo.pose.x, 1e-12);
    CPPUNIT_ASSERT_THROW(playback.odometryAt(-1.0, 0.0), NotAvailableError);
    CPPUNIT_ASSERT_THROW(playback.odometryAt(42.0, 0.0), NotAvailableError);
  }
  void smallBufferDropsOldScans() {
    LogPlayback playback(std::make_unique<TenSecondLog>(), parseReplayMode("realtime"), 3);
    const auto batch = playback.scansSince(0, 100, 100.0);
    CPPUNIT_ASSERT_EQUAL(DataId(8), batch.records.front().id);
    CPPUNIT_ASSERT_EQUAL(DataId(8), playback.oldestScanId());
    CPPUNIT_ASSERT_THROW(playback.scan(2, 100.0), NotAvailableError);
    CPPUNIT_ASSERT_THROW(playback.scan(0, 100.0), InvalidArgumentError);
  }
  void slowestActiveConsumerPacesTheReplay() {
    LogPlayback playback(std::make_unique<TenSecondLog>(), parseReplayMode("max"), 3);
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), playback.scansSince(0, 3, 0.0, "slow").records.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t(3), playback.scansSince(0, 3, 0.0, "fast").records.size());
    // An odometry reader far ahead must not push out scans 1..3 the scan readers have not confirmed.
    CPPUNIT_ASSERT_THROW(playback.odometryAt(100.0, 0.1), NotAvailableError);
    CPPUNIT_ASSERT_EQUAL(DataId(1), playback.scansSince(0, 3, 0.2, "slow").records.front().id);
    // The fast reader confirms 1..3, but the slow one has not: nothing moves on.
    CPPUNIT_ASSERT(playback.scansSince(3, 3, 0.3, "fast").records.empty());
    // Once the slow one confirms them too, the replay moves on.
    CPPUNIT_ASSERT_EQUAL(DataId(4), playback.scansSince(3, 3, 0.3, "slow").records.front().id);
    CPPUNIT_ASSERT_EQUAL(DataId(4), playback.scansSince(3, 3, 0.3, "fast").records.front().id);
    // A scan reader silent for longer than the idle limit no longer holds the replay back.
    const double later = 0.3 + LogPlayback::kConsumerIdleSeconds;
    CPPUNIT_ASSERT_DOUBLES_EQUAL(10.0, playback.odometryAt(9.0, later).pose.x, 1e-9);
  }
  void consumersAreBoundedAndForgotten() {
    LogPlayback playback(std::make_unique<TenSecondLog>(), parseReplayMode("max"), 3);
    for (int i = 0; i < 1000; ++i) playback.scansSince(0, 1, 0.0, "caller-" + std::to_string(i));
    CPPUNIT_ASSERT_EQUAL(LogPlayback::kMaxConsumers, playback.scanConsumers());
    // After the idle time only the caller that asks again is remembered.
    playback.scansSince(0, 1, LogPlayback::kConsumerIdleSeconds, "ScanMapper");
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, playback.scanConsumers());
  }
  void replaysTheWholeIntelLogInOrder() {
    LogPlayback playback(openLog(sharedPath("data/laser/corrected/intel-corrected.log.gz")),
                         parseReplayMode("max"), 2000);
    DataId last = 0;
    std::size_t received = 0;
    for (;;) {
      const auto batch = playback.scansSince(last, 50, 0.0);
      for (const auto& scan : batch.records) {
        CPPUNIT_ASSERT_EQUAL(last + 1, scan.id);
        last = scan.id;
        ++received;
      }
      if (batch.records.empty() && batch.endOfData) break;
    }
    CPPUNIT_ASSERT_EQUAL(std::size_t(910), received);
    CPPUNIT_ASSERT(playback.readError().empty());
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(LogPlaybackTest);
