// Tests InputFollower on a fake input of numbered records: a record that always fails is tried
// kAttemptsPerRecord times, then skipped, counted and logged, and the records after it are taken
// in; a record that fails only once is retried, not skipped; an input module that is away is a
// health error, never a skip; the thread survives exceptions of any type.
#include <cppunit/extensions/HelperMacros.h>

#include <condition_variable>
#include <map>
#include <mutex>
#include <set>
#include <stdexcept>
#include <vector>

#include "clientlibs/common/ClientConnection.h"
#include "servers/common/InputFollower.h"

using namespace rgnav;

namespace {

// Records 1..last; `failures[id]` of them throw (-1: always) before they are taken in.
struct FakeInput {
  std::mutex mutex;
  std::condition_variable changed;
  std::uint64_t next = 1, last = 6;
  std::map<std::uint64_t, int> failures;
  std::map<std::uint64_t, int> attempts;
  std::vector<std::uint64_t> taken, skipped;
  int away = 0;  // steps that find the input module away

  bool step() {
    std::lock_guard lock(mutex);
    if (away > 0) {
      --away;
      changed.notify_all();
      throw ModuleUnavailableError("Laser.scansSince: no answer");
    }
    if (next > last) return false;
    ++attempts[next];
    int& left = failures[next];
    if (left != 0) {
      if (left > 0) --left;
      changed.notify_all();
      if (next % 2 == 0) throw std::out_of_range("vector::at");
      throw 7;
    }
    taken.push_back(next++);
    changed.notify_all();
    return true;
  }
  std::string skip() {
    std::lock_guard lock(mutex);
    skipped.push_back(next);
    changed.notify_all();
    return "record " + std::to_string(next++);
  }
  template <class Done>
  bool waitFor(Done done) {
    std::unique_lock lock(mutex);
    return changed.wait_for(lock, std::chrono::seconds(30), done);
  }
  // Follows the input until every record is taken in or skipped; the follower's health after.
  ModuleStatusInfo followToTheEnd() {
    ModuleHealth health;
    InputFollower follower(health, "laser", [&] { return step(); }, [&] { return skip(); },
                           std::chrono::milliseconds(1));
    follower.start();
    CPPUNIT_ASSERT(waitFor([&] { return next > last; }));
    follower.stop();
    return health.snapshot();
  }
};

}  // namespace

class InputFollowerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(InputFollowerTest);
  CPPUNIT_TEST(aBadRecordIsSkippedAfterItsAttempts);
  CPPUNIT_TEST(anInputAwayIsNoBadRecord);
  CPPUNIT_TEST_SUITE_END();

 public:
  void aBadRecordIsSkippedAfterItsAttempts() {
    FakeInput input;
    input.failures = {{2, 1}, {4, -1}, {5, -1}};
    const ModuleStatusInfo status = input.followToTheEnd();
    CPPUNIT_ASSERT(std::vector<std::uint64_t>({1, 2, 3, 6}) == input.taken);
    CPPUNIT_ASSERT(std::vector<std::uint64_t>({4, 5}) == input.skipped);
    CPPUNIT_ASSERT_EQUAL(InputFollower::kAttemptsPerRecord, input.attempts[4]);
    CPPUNIT_ASSERT_EQUAL(2, input.attempts[2]);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{2}, status.counters.at("input_records_skipped"));
    CPPUNIT_ASSERT_EQUAL(std::uint64_t{1 + 2 * InputFollower::kAttemptsPerRecord}, status.counters.at("input_failures"));
  }

  void anInputAwayIsNoBadRecord() {
    FakeInput input;
    input.away = 2 * InputFollower::kAttemptsPerRecord;
    const ModuleStatusInfo status = input.followToTheEnd();
    CPPUNIT_ASSERT(input.skipped.empty());
    CPPUNIT_ASSERT_EQUAL(std::size_t{6}, input.taken.size());
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, status.counters.count("input_records_skipped"));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(InputFollowerTest);
