// Tests CheckpointWriter with files the test holds up or makes fail: handing checkpoints over
// never waits for a write under way, the journal lines arrive complete, in order and exactly
// once also when map writes fail (before, each failed attempt appended all pending lines again:
// a journal quadratic in the scans), the newest map wins, the durable revision follows what was
// written, and a failed write degrades the module, waits its backoff instead of being retried
// with every checkpoint handed over, and is retried on its own until it succeeds.
#include <cppunit/extensions/HelperMacros.h>

#include <condition_variable>
#include <mutex>
#include <vector>

#include "core/common/Errors.h"
#include "servers/rgmappingkernel/CheckpointWriter.h"
#include "tests/support/WaitUntil.h"

using namespace rgnav;
using std::chrono::hours;
using std::chrono::milliseconds;

namespace {

// Files that record what they got; while held, the map write waits until released; the journal
// append fails while journalFailures > 0, the map write while mapFailures > 0 (each failure
// counting one down).
struct FakeDisk {
  std::mutex mutex;
  std::condition_variable changed;
  bool held = false, inside = false;
  int journalFailures = 0, mapFailures = 0, mapAttempts = 0;
  std::string journal;
  std::vector<std::string> maps;

  CheckpointWriter::Files files() {
    return {[this](const std::string& lines) {
              std::lock_guard lock(mutex);
              if (journalFailures > 0 && journalFailures-- > 0) throw FileError("journal: No space left on device");
              journal += lines;
            },
            [this](const std::string& map) {
              std::unique_lock lock(mutex);
              ++mapAttempts;
              inside = true;
              changed.notify_all();
              changed.wait(lock, [&] { return !held; });
              inside = false;
              if (mapFailures > 0 && mapFailures-- > 0) throw FileError("map: Read-only file system");
              maps.push_back(map);
            }};
  }
  void hold() {
    std::lock_guard lock(mutex);
    held = true;
  }
  void waitInside() {
    std::unique_lock lock(mutex);
    changed.wait(lock, [&] { return inside; });
  }
  void release() {
    {
      std::lock_guard lock(mutex);
      held = false;
    }
    changed.notify_all();
  }
  template <class T>
  T read(T FakeDisk::*field) {
    std::lock_guard lock(mutex);
    return this->*field;
  }
};

// The journal line of scan `id`.
std::string line(int id) {
  std::string text = std::to_string(id);
  text.insert(text.begin(), 's');
  text += '\n';
  return text;
}

}  // namespace

class CheckpointWriterTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CheckpointWriterTest);
  CPPUNIT_TEST(handingOverNeverWaitsForAWrite);
  CPPUNIT_TEST(aFailedAppendKeepsItsJournalLines);
  CPPUNIT_TEST(failedMapWritesAppendEachLineOnce);
  CPPUNIT_TEST(aFailureWaitsItsBackoff);
  CPPUNIT_TEST(aFailureIsRetriedOnItsOwnUntilItSucceeds);
  CPPUNIT_TEST_SUITE_END();

 public:
  void setUp() override { health_.setState(ModuleRunState::Running); }

  void handingOverNeverWaitsForAWrite() {
    CheckpointWriter writer(disk_.files(), health_, 3);
    disk_.hold();
    writer.submit("s1\n", "map1", 4);
    disk_.waitInside();  // the first write is under way and cannot end
    writer.submit("s2\n", "map2", 5);
    writer.submit("s3\n", "map3", 6);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{3}, writer.durableRevision());
    disk_.release();
    writer.flush();
    CPPUNIT_ASSERT_EQUAL(std::string("s1\ns2\ns3\n"), disk_.journal);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, disk_.maps.size());  // map2 was superseded while waiting
    CPPUNIT_ASSERT_EQUAL(std::string("map3"), disk_.maps.back());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{6}, writer.durableRevision());
  }

  void aFailedAppendKeepsItsJournalLines() {
    CheckpointWriter writer(disk_.files(), health_, 0, kNoRetry, kNoRetry);
    disk_.journalFailures = 1;
    writer.submit("s1\n", "map1", 1);
    writer.flush();
    CPPUNIT_ASSERT(health_.snapshot().state == ModuleRunState::Degraded);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{0}, writer.durableRevision());
    CPPUNIT_ASSERT_EQUAL(0, disk_.mapAttempts);  // no map without its scans in the journal
    writer.submit("s2\n", "map2", 2);
    writer.flush();
    CPPUNIT_ASSERT_EQUAL(std::string("s1\ns2\n"), disk_.journal);
    CPPUNIT_ASSERT_EQUAL(std::string("map2"), disk_.maps.back());
    CPPUNIT_ASSERT(health_.snapshot().state == ModuleRunState::Running);
    CPPUNIT_ASSERT(health_.snapshot().lastError.empty());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{2}, writer.durableRevision());
  }

  void failedMapWritesAppendEachLineOnce() {
    CheckpointWriter writer(disk_.files(), health_, 0, kNoRetry, kNoRetry);
    disk_.mapFailures = 5;
    std::string expected;
    for (int scan = 1; scan <= 6; ++scan) {
      expected += line(scan);
      writer.submit(line(scan), std::to_string(scan), scan);
      writer.flush();  // one attempt each: five fail, the sixth writes map 6
    }
    CPPUNIT_ASSERT_EQUAL(6, disk_.mapAttempts);
    CPPUNIT_ASSERT_EQUAL(expected, disk_.journal);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, disk_.maps.size());
    CPPUNIT_ASSERT_EQUAL(std::string("6"), disk_.maps.front());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{6}, writer.durableRevision());
  }

  void aFailureWaitsItsBackoff() {
    CheckpointWriter writer(disk_.files(), health_, 0, kNoRetry, kNoRetry);
    disk_.mapFailures = 1;
    writer.submit("s1\n", "map1", 1);
    writer.flush();
    for (int scan = 2; scan <= 50; ++scan) writer.submit(line(scan), "map", scan);
    // A write under way would have to take the map; none starts before the backoff's end.
    CPPUNIT_ASSERT_EQUAL(1, disk_.read(&FakeDisk::mapAttempts));
    const ModuleStatusInfo s = health_.snapshot();
    CPPUNIT_ASSERT(s.state == ModuleRunState::Degraded);
    CPPUNIT_ASSERT_EQUAL(std::string("checkpoint: map: Read-only file system"), s.lastError);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{1}, s.counters.at("checkpoint_failures"));
  }

  void aFailureIsRetriedOnItsOwnUntilItSucceeds() {
    CheckpointWriter writer(disk_.files(), health_, 0, milliseconds(1), milliseconds(4));
    disk_.mapFailures = 3;
    writer.submit("s1\n", "map1", 1);  // nothing else is handed over: the writer retries alone
    testing::waitUntil([&] { return writer.durableRevision() == 1; }, "the retried checkpoint");
    CPPUNIT_ASSERT_EQUAL(4, disk_.read(&FakeDisk::mapAttempts));
    CPPUNIT_ASSERT_EQUAL(std::string("s1\n"), disk_.read(&FakeDisk::journal));
    CPPUNIT_ASSERT(health_.snapshot().state == ModuleRunState::Running);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{3}, health_.snapshot().counters.at("checkpoint_failures"));
  }
 private:
  // A backoff that outlasts the test: after a failure only flush() makes the next attempt.
  static constexpr hours kNoRetry{1};

  FakeDisk disk_;
  ModuleHealth health_;
};

CPPUNIT_TEST_SUITE_REGISTRATION(CheckpointWriterTest);
