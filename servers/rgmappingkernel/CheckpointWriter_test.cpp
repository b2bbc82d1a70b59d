// Tests CheckpointWriter with a write the test holds up: handing checkpoints over never waits
// for a write under way, the journal lines arrive complete and in order, the newest map wins,
// the durable revision follows what was written, and a failed write keeps its journal lines for
// the next one.
#include <cppunit/extensions/HelperMacros.h>

#include <condition_variable>
#include <mutex>
#include <vector>

#include "core/common/Errors.h"
#include "servers/rgmappingkernel/CheckpointWriter.h"

using namespace rgnav;

namespace {

// A write that records what it got and, while held, waits until released.
struct HeldWrite {
  std::mutex mutex;
  std::condition_variable changed;
  bool held = false, inside = false, fail = false;
  std::string journal;
  std::vector<std::string> maps;

  CheckpointWriter::Write write() {
    return [this](const std::string& j, const std::string& m) {
      std::unique_lock lock(mutex);
      inside = true;
      changed.notify_all();
      changed.wait(lock, [&] { return !held; });
      inside = false;
      if (fail) throw FileError("disk full");
      journal += j;
      maps.push_back(m);
    };
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
};

}  // namespace

class CheckpointWriterTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(CheckpointWriterTest);
  CPPUNIT_TEST(handingOverNeverWaitsForAWrite);
  CPPUNIT_TEST(aFailedWriteKeepsItsJournalLines);
  CPPUNIT_TEST_SUITE_END();

 public:
  void handingOverNeverWaitsForAWrite() {
    HeldWrite disk;
    ModuleHealth health;
    CheckpointWriter writer(disk.write(), health, 3);
    disk.hold();
    writer.submit("s1\n", "map1", 4);
    disk.waitInside();  // the first write is under way and cannot end
    writer.submit("s2\n", "map2", 5);
    writer.submit("s3\n", "map3", 6);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{3}, writer.durableRevision());
    disk.release();
    writer.flush();
    CPPUNIT_ASSERT_EQUAL(std::string("s1\ns2\ns3\n"), disk.journal);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, disk.maps.size());  // map2 was superseded while waiting
    CPPUNIT_ASSERT_EQUAL(std::string("map3"), disk.maps.back());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{6}, writer.durableRevision());
  }

  void aFailedWriteKeepsItsJournalLines() {
    HeldWrite disk;
    ModuleHealth health;
    CheckpointWriter writer(disk.write(), health, 0);
    disk.fail = true;
    writer.submit("s1\n", "map1", 1);
    writer.flush();
    CPPUNIT_ASSERT(!health.snapshot().lastError.empty());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{0}, writer.durableRevision());
    disk.fail = false;
    writer.submit("s2\n", "map2", 2);
    writer.flush();
    CPPUNIT_ASSERT_EQUAL(std::string("s1\ns2\n"), disk.journal);
    CPPUNIT_ASSERT(health.snapshot().lastError.empty());
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{2}, writer.durableRevision());
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(CheckpointWriterTest);
