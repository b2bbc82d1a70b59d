// KernelFeed: the kernel gets scans, events and pose revisions in the contract's order whatever
// the inputs' timing. The inputs are fakes serving a scripted two-room tour (SyntheticTour) with
// pose revisions made at fixed scans: a feed whose inputs lag (few scans visible at a time, the
// detector behind the ScanMapper, small fetches) or whose ScanMapper restarts and makes its
// revisions again later ends with exactly the state of a kernel fed by hand in contract order;
// one whose ScanMapper forgets revisions before the feed reads them counts that and ends with
// the latest poses.
#include <cppunit/extensions/HelperMacros.h>

#include <algorithm>
#include <mutex>

#include "core/common/Errors.h"
#include "core/rgmap/feed/KernelFeed.h"
#include "core/rgmap/kernel/RgMapCodec.h"
#include "core/rgmap/kernel/RgMapConsistency.h"
#include "core/rgmap/kernel/testing/SyntheticTour.h"

using namespace rgnav;

namespace {

// A scripted mapping run: every scan with its tour pose, the events, and revision k (1, 2, ...)
// made while scan revisionScans[k-1] was taken in; the last one may be made after the last scan.
struct Script {
  std::vector<StoredScan> scans;
  std::vector<GatewayEvent> events;
  std::vector<DataId> revisionScans;

  DataId lastScan() const { return scans.back().scan.id; }
  // Revisions made before scan `id` was taken in.
  std::uint64_t revisionsBefore(DataId id) const {
    return std::count_if(revisionScans.begin(), revisionScans.end(), [id](DataId at) { return at <= id; });
  }
  // Scan `id`'s pose right after revision `revision`: each revision moves the map a little.
  Pose2D poseAfter(DataId id, std::uint64_t revision) const {
    const Pose2D p = scans.at(id - 1).corrected;
    return {p.x + 0.02 * double(revision), p.y - 0.01 * double(revision), p.theta};
  }
};

Script twoRoomScript() {
  Script s;
  const rgnav::testing::SyntheticTour tour = rgnav::testing::twoRoomTour();
  for (const rgnav::testing::KernelInput& input : tour.inputs()) {
    if (input.scan) s.scans.push_back(*input.scan);
    if (input.event) {
      s.events.push_back(*input.event);
      s.events.back().scanId = s.scans.back().scan.id;  // caused by the scan before it
    }
  }
  const DataId last = s.scans.back().scan.id;
  s.revisionScans = {last / 5, last / 3, last / 2, last / 2 + 1, (3 * last) / 4, last + 1};
  return s;
}

class FakeScanMapper : public CorrectedScanInput {
 public:
  explicit FakeScanMapper(const Script& script) : script_(script), visible_(script.lastScan()) {}

  void setVisible(DataId last) { visible_ = std::min(last, script_.lastScan()); }
  void setEnded(bool ended) { ended_ = ended; }
  // A restart: the revisions made so far must be made again (remake()).
  void restart() { remadeUpTo_ = 0; }
  void remake() { remadeUpTo_.reset(); }
  // Keeps only the latest `n` revisions.
  void keepOnly(std::size_t n) { kept_ = n; }

  std::uint64_t made() const {
    const std::uint64_t m = script_.revisionsBefore(visible_ + (ended_ ? 1 : 0));
    return remadeUpTo_ ? std::min(m, *remadeUpTo_) : m;
  }

  CorrectedBatch correctedSince(DataId afterId, std::uint32_t maxCount) override {
    CorrectedBatch b;
    b.latestId = visible_;
    b.revision = made();
    for (DataId id = afterId + 1; id <= visible_ && b.scans.size() < maxCount; ++id) {
      const Pose2D mapped = script_.poseAfter(id, script_.revisionsBefore(id));
      b.scans.push_back({script_.scans[id - 1].scan, script_.poseAfter(id, made()), mapped, false});
    }
    b.endOfData = ended_ && visible_ == script_.lastScan() && (b.scans.empty() ? afterId : b.scans.back().scan.id) >= visible_;
    return b;
  }
  std::vector<PoseRevisionInfo> revisionsSince(std::uint64_t afterRevision) override {
    std::vector<PoseRevisionInfo> out;
    for (std::uint64_t r = afterRevision + 1; r <= made(); ++r)
      if (isKept(r)) out.push_back({r, script_.revisionScans[r - 1]});
    return out;
  }
  std::vector<PoseUpdate> revisedPoses(std::uint64_t revision, DataId firstId, DataId lastId) override {
    if (revision > made() || !isKept(revision)) throw NotAvailableError("revision not kept");
    CPPUNIT_ASSERT(lastId < script_.revisionScans[revision - 1]);
    return posesOf(firstId, lastId, revision);
  }
  std::vector<PoseUpdate> poses(DataId firstId, DataId lastId) override {
    return posesOf(firstId, std::min(lastId, visible_), made());
  }
  std::uint64_t revision() override { return made(); }

 private:
  bool isKept(std::uint64_t r) const { return !kept_ || r + *kept_ > made(); }
  // Two at a time, so the feed has to ask again.
  std::vector<PoseUpdate> posesOf(DataId first, DataId last, std::uint64_t revision) const {
    std::vector<PoseUpdate> out;
    for (DataId id = first; id <= last && out.size() < 2; ++id) out.push_back({id, script_.poseAfter(id, revision)});
    return out;
  }

  const Script& script_;
  DataId visible_;
  bool ended_ = true;
  std::optional<std::uint64_t> remadeUpTo_;
  std::optional<std::size_t> kept_;
};

class FakeDetection : public GatewayEventInput {
 public:
  explicit FakeDetection(const Script& script) : script_(script), processed_(script.lastScan()) {}

  void setProcessed(DataId last) { processed_ = std::min(last, script_.lastScan()); }
  void setEnded(bool ended) { ended_ = ended; }

  GatewayEventBatch eventsSince(GatewayEventId afterId, std::uint32_t maxCount) override {
    GatewayEventBatch b;
    b.lastScan = processed_;
    for (const GatewayEvent& e : script_.events) {
      if (e.scanId > processed_) break;
      b.latestId = e.id;
      if (e.id > afterId && b.events.size() < maxCount) b.events.push_back(e);
    }
    b.endOfData = ended_ && processed_ == script_.lastScan() &&
                  (b.events.empty() ? afterId : b.events.back().id) >= b.latestId;
    return b;
  }

 private:
  const Script& script_;
  DataId processed_;
  bool ended_ = true;
};

std::vector<CorrectedPose> posesUpTo(const Script& s, DataId last, std::uint64_t revision) {
  std::vector<CorrectedPose> out;
  for (DataId id = 1; id <= last; ++id) out.push_back({id, s.poseAfter(id, revision)});
  return out;
}

// The contract, spelled out: before scan s the revisions made at s, then scan s as mapped, then
// its events; at the end the revisions made after the last scan and the final poses.
RgMapState fedInContractOrder(const Script& s) {
  RgMappingKernel kernel;
  std::size_t next = 0;
  for (const StoredScan& stored : s.scans) {
    const DataId id = stored.scan.id;
    for (std::uint64_t r = 1; r <= s.revisionScans.size(); ++r)
      if (s.revisionScans[r - 1] == id) kernel.revisePoses(posesUpTo(s, id - 1, r), r);
    kernel.addScan(stored.scan, s.poseAfter(id, s.revisionsBefore(id)));
    for (; next < s.events.size() && s.events[next].scanId <= id; ++next)
      kernel.addGatewayEvent(s.events[next], kernel.state().scans.at(s.events[next].gateway.lastScan).corrected);
  }
  const std::uint64_t all = s.revisionScans.size();
  for (std::uint64_t r = s.revisionsBefore(s.lastScan()) + 1; r <= all; ++r)
    kernel.revisePoses(posesUpTo(s, s.lastScan(), r), r);
  kernel.revisePoses(posesUpTo(s, s.lastScan(), all), all);
  return kernel.state();
}

// Steps the feed until it finishes; `between` changes the inputs before each step.
template <class F>
void runToEnd(KernelFeed& feed, std::mutex& mutex, F between) {
  for (int step = 0; step < 100000; ++step) {
    between(step);
    feed.step();
    std::lock_guard lock(mutex);
    if (feed.finished()) return;
  }
  CPPUNIT_FAIL("the feed did not finish");
}

}  // namespace

class KernelFeedTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(KernelFeedTest);
  CPPUNIT_TEST(testPromptInputsGiveTheContractOrder);
  CPPUNIT_TEST(testLaggingInputsGiveTheSameMap);
  CPPUNIT_TEST(testRestartedScanMapperIsWaitedFor);
  CPPUNIT_TEST(testForgottenRevisionsAreCountedAndReplaced);
  CPPUNIT_TEST(testZeroFetchBatchIsRefused);
  CPPUNIT_TEST_SUITE_END();

 public:
  void setUp() override { script_ = twoRoomScript(); }

  void testPromptInputsGiveTheContractOrder() {
    const RgMapState expected = fedInContractOrder(script_);
    CPPUNIT_ASSERT(checkConsistency(expected).empty());
    CPPUNIT_ASSERT(expected.regions.size() >= 3);
    FakeScanMapper scans(script_);
    FakeDetection events(script_);
    RgMappingKernel kernel;
    std::mutex mutex;
    KernelFeed feed(kernel, mutex, scans, events, 100);
    runToEnd(feed, mutex, [](int) {});
    CPPUNIT_ASSERT_EQUAL(serializeRgMap(expected), serializeRgMap(kernel.state()));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(script_.scans.size()), feed.counters().scansMapped);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(script_.events.size()), feed.counters().gatewayEventsMapped);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), feed.counters().posesReplaced);
  }

  void testLaggingInputsGiveTheSameMap() {
    FakeScanMapper scans(script_);
    FakeDetection events(script_);
    scans.setEnded(false);
    events.setEnded(false);
    RgMappingKernel kernel;
    std::mutex mutex;
    KernelFeed feed(kernel, mutex, scans, events, 3);
    const DataId last = script_.lastScan();
    runToEnd(feed, mutex, [&](int step) {
      const DataId visible = DataId(step) / 2 + 1;  // the ScanMapper gains a scan every second step
      scans.setVisible(visible);
      events.setProcessed(visible > 7 ? visible - 7 : 0);  // the detector lags seven scans behind
      scans.setEnded(visible >= last);
      events.setEnded(visible >= last + 7);
    });
    CPPUNIT_ASSERT_EQUAL(serializeRgMap(fedInContractOrder(script_)), serializeRgMap(kernel.state()));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(script_.revisionScans.size()), feed.counters().poseRevisions);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), feed.counters().posesReplaced);
  }

  void testRestartedScanMapperIsWaitedFor() {
    FakeScanMapper scans(script_);
    FakeDetection events(script_);
    RgMappingKernel kernel;
    std::mutex mutex;
    KernelFeed feed(kernel, mutex, scans, events, 5);
    const DataId restartAt = script_.revisionScans[2] - 1;  // revisions 1 and 2 made, 3 next
    scans.setVisible(restartAt);
    events.setProcessed(0);  // the kernel cannot go on: it learns of the revisions first
    scans.setEnded(false);
    events.setEnded(false);
    feed.step();
    scans.restart();  // forgets what it made; the feed must not apply the latest poses instead
    events.setProcessed(restartAt);
    for (int i = 0; i < 5; ++i) feed.step();
    {
      std::lock_guard lock(mutex);
      CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), kernel.state().lastPoseRevision);
      CPPUNIT_ASSERT(kernel.state().lastScanId < script_.revisionScans[0]);
    }
    scans.remake();
    runToEnd(feed, mutex, [&](int) {
      scans.setVisible(script_.lastScan());
      events.setProcessed(script_.lastScan());
      scans.setEnded(true);
      events.setEnded(true);
    });
    CPPUNIT_ASSERT_EQUAL(serializeRgMap(fedInContractOrder(script_)), serializeRgMap(kernel.state()));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), feed.counters().posesReplaced);
  }

  void testForgottenRevisionsAreCountedAndReplaced() {
    FakeScanMapper scans(script_);
    FakeDetection events(script_);
    scans.keepOnly(1);
    events.setProcessed(0);  // the detector holds the kernel back while the ScanMapper maps all
    events.setEnded(false);
    RgMappingKernel kernel;
    std::mutex mutex;
    KernelFeed feed(kernel, mutex, scans, events, 100);
    feed.step();
    runToEnd(feed, mutex, [&](int) {
      events.setProcessed(script_.lastScan());
      events.setEnded(true);
    });
    std::lock_guard lock(mutex);
    const std::uint64_t all = script_.revisionScans.size();
    CPPUNIT_ASSERT_EQUAL(all - 1, feed.counters().revisionsNotKept);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(1), feed.counters().poseRevisions);
    CPPUNIT_ASSERT_EQUAL(all, kernel.state().lastPoseRevision);
    for (const auto& [id, stored] : kernel.state().scans)
      CPPUNIT_ASSERT(stored.corrected == script_.poseAfter(id, all));
    CPPUNIT_ASSERT(checkConsistency(kernel.state()).empty());
  }

  void testZeroFetchBatchIsRefused() {
    FakeScanMapper scans(script_);
    FakeDetection events(script_);
    RgMappingKernel kernel;
    std::mutex mutex;
    CPPUNIT_ASSERT_THROW(KernelFeed(kernel, mutex, scans, events, 0), InvalidArgumentError);
  }

 private:
  Script script_;
};

CPPUNIT_TEST_SUITE_REGISTRATION(KernelFeedTest);
