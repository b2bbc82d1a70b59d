// Tests the SlamState checkpoint: serialisation round trip (kept revisions included), typed errors
// for corrupt bytes and inconsistent states, and that a mapper restored from bytes and fed the rest of a log ends with
// exactly the state of an uninterrupted run (real Intel keyframes with raw odometry, and the
// synthetic ring with its loop closures).
#include <cppunit/extensions/HelperMacros.h>

#include "core/logs/IntelJsonLogReader.h"
#include "core/logs/LogTestFiles.h"
#include "core/slam/ScanMapper.h"
#include "core/slam/SlamStateCodec.h"
#include "core/slam/testing/SyntheticWorld.h"

namespace {

std::vector<rgnav::LaserScan> intelScans(std::size_t count) {
  rgnav::IntelJsonLogReader reader(rgnav::testing::sharedData("laser/derived/xiaofeng-intel_gfs.json.xz"));
  auto scans = rgnav::testing::readAll(reader).scans;
  scans.resize(count);
  return scans;
}

rgnav::SlamState uninterrupted(const std::vector<rgnav::LaserScan>& scans) {
  rgnav::ScanMapper mapper;
  for (const auto& scan : scans) mapper.addScan(scan);
  return mapper.state();
}

// Feeds scans [0, split), checkpoints to bytes, restores a new mapper and feeds the rest.
rgnav::SlamState restarted(const std::vector<rgnav::LaserScan>& scans, std::size_t split) {
  std::string bytes;
  {
    rgnav::ScanMapper mapper;
    for (std::size_t i = 0; i < split; ++i) mapper.addScan(scans[i]);
    bytes = rgnav::serializeState(mapper.state());
  }
  rgnav::ScanMapper mapper({}, rgnav::deserializeState(bytes));
  CPPUNIT_ASSERT_EQUAL(scans[split - 1].id, mapper.lastInputId());
  for (std::size_t i = split; i < scans.size(); ++i) mapper.addScan(scans[i]);
  return mapper.state();
}

void assertRestartChangesNothing(const std::vector<rgnav::LaserScan>& scans, std::size_t split) {
  const rgnav::SlamState reference = uninterrupted(scans);
  CPPUNIT_ASSERT(reference.counters.loopClosures > 0);
  CPPUNIT_ASSERT(reference.counters.optimizations > 0);
  const rgnav::SlamState resumed = restarted(scans, split);
  CPPUNIT_ASSERT_EQUAL(reference.keyframes.size(), resumed.keyframes.size());
  for (std::size_t k = 0; k < reference.keyframes.size(); ++k)
    CPPUNIT_ASSERT(reference.keyframes[k].pose == resumed.keyframes[k].pose);  // bit-exact
  CPPUNIT_ASSERT(reference == resumed);
}

}  // namespace

class SlamStateTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SlamStateTest);
  CPPUNIT_TEST(roundTripIsExact);
  CPPUNIT_TEST(corruptBytesAreTypedErrors);
  CPPUNIT_TEST(inconsistentStatesAreRejected);
  CPPUNIT_TEST(restoreThenContinueEqualsUninterruptedIntel);
  CPPUNIT_TEST(restoreThenContinueEqualsUninterruptedRing);
  CPPUNIT_TEST_SUITE_END();

 public:
  void roundTripIsExact() {
    const rgnav::SlamState state = uninterrupted(intelScans(120));
    CPPUNIT_ASSERT(!state.constraints.empty() && !state.submaps.empty());
    const std::string bytes = rgnav::serializeState(state);
    CPPUNIT_ASSERT(rgnav::deserializeState(bytes) == state);
    CPPUNIT_ASSERT(rgnav::deserializeState(rgnav::serializeState({})) == rgnav::SlamState{});
    const rgnav::SlamState revised = uninterrupted(rgnav::testing::ringRun().scans);
    CPPUNIT_ASSERT(!revised.revisions.empty());
    CPPUNIT_ASSERT(rgnav::deserializeState(rgnav::serializeState(revised)) == revised);
  }
  void corruptBytesAreTypedErrors() {
    const std::string bytes = rgnav::serializeState(uninterrupted(intelScans(30)));
    CPPUNIT_ASSERT_THROW(rgnav::deserializeState(bytes.substr(0, bytes.size() - 1)), rgnav::CorruptStateError);
    CPPUNIT_ASSERT_THROW(rgnav::deserializeState(bytes + "x"), rgnav::CorruptStateError);
    CPPUNIT_ASSERT_THROW(rgnav::deserializeState("not a state"), rgnav::CorruptStateError);
    std::string version = bytes;
    version[8] = 9;
    CPPUNIT_ASSERT_THROW(rgnav::deserializeState(version), rgnav::CorruptStateError);
    std::string hugeCount = bytes;
    hugeCount[19] = static_cast<char>(0x7f);  // the scan count's high byte
    CPPUNIT_ASSERT_THROW(rgnav::deserializeState(hugeCount), rgnav::CorruptStateError);
  }
  void inconsistentStatesAreRejected() {
    rgnav::SlamState state = uninterrupted(intelScans(30));
    rgnav::SlamState badConstraint = state;
    badConstraint.constraints.front().to = 1000;
    CPPUNIT_ASSERT_THROW(rgnav::ScanMapper({}, badConstraint), rgnav::InvalidArgumentError);
    CPPUNIT_ASSERT_THROW(rgnav::deserializeState(rgnav::serializeState(badConstraint)), rgnav::CorruptStateError);
    rgnav::SlamState badIds = state;
    badIds.scans[3].id = badIds.scans[2].id;
    CPPUNIT_ASSERT_THROW(rgnav::validate(badIds), rgnav::InvalidArgumentError);
    rgnav::SlamState ring = uninterrupted(rgnav::testing::ringRun().scans);
    rgnav::SlamState lateRevision = ring;
    lateRevision.revisions.back().number = ring.counters.optimizations + 1;
    CPPUNIT_ASSERT_THROW(rgnav::validate(lateRevision), rgnav::InvalidArgumentError);
    rgnav::SlamState shortRevision = ring;
    shortRevision.revisions.back().keyframePoses.resize(1);
    CPPUNIT_ASSERT_THROW(rgnav::deserializeState(rgnav::serializeState(shortRevision)), rgnav::CorruptStateError);
  }
  void restoreThenContinueEqualsUninterruptedIntel() { assertRestartChangesNothing(intelScans(250), 137); }
  void restoreThenContinueEqualsUninterruptedRing() {
    const auto scans = rgnav::testing::ringRun().scans;
    assertRestartChangesNothing(scans, scans.size() * 3 / 4);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(SlamStateTest);
