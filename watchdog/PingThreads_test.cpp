// Tests the watchdog's ping threads: each asked ping runs once and its outcome reaches the
// callback, and a module whose ping blocks holds up no other module's ping.
#include <cppunit/extensions/HelperMacros.h>

#include <atomic>
#include <map>
#include <mutex>

#include "watchdog/PingThreads.h"
#include "watchdog/testing/Wait.h"

using rgnav::PingThreads;
using rgnav::testing::waitUntil;

namespace {

// The outcomes the callback saw, by module.
class Outcomes {
 public:
  PingThreads::OnResult callback() {
    return [this](const std::string& module, bool answered) {
      std::lock_guard lock(mutex_);
      seen_.emplace(module, answered);
    };
  }
  bool has(const std::string& module) {
    std::lock_guard lock(mutex_);
    return seen_.count(module) > 0;
  }
  std::multimap<std::string, bool> all() {
    std::lock_guard lock(mutex_);
    return seen_;
  }

 private:
  std::mutex mutex_;
  std::multimap<std::string, bool> seen_;
};

}  // namespace

class PingThreadsTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(PingThreadsTest);
  CPPUNIT_TEST(outcomesReachTheCallback);
  CPPUNIT_TEST(aBlockedPingHoldsUpNoOther);
  CPPUNIT_TEST_SUITE_END();

 public:
  void outcomesReachTheCallback() {
    Outcomes outcomes;
    std::atomic<int> calls{0};
    // Each ping asks for the process it was given: A's answers, B's is another one.
    PingThreads pings({{"A", [&](pid_t pid) { ++calls; return pid == 42; }},
                       {"B", [&](pid_t pid) { ++calls; return pid == 42; }}},
                      outcomes.callback());
    pings.ping("A", 42);
    pings.ping("B", 43);
    waitUntil([&] { return outcomes.has("A") && outcomes.has("B"); }, "both outcomes");
    pings.stop();
    CPPUNIT_ASSERT((outcomes.all() == std::multimap<std::string, bool>{{"A", true}, {"B", false}}));
    CPPUNIT_ASSERT_EQUAL(2, calls.load());
  }

  void aBlockedPingHoldsUpNoOther() {
    Outcomes outcomes;
    std::atomic<bool> release{false};
    PingThreads pings({{"Hung", [&](pid_t) {
                         waitUntil([&] { return release.load(); }, "the test to release the hung ping");
                         return false;
                       }},
                       {"Fine", [](pid_t) { return true; }}},
                      outcomes.callback());
    pings.ping("Hung", 42);
    pings.ping("Fine", 43);
    waitUntil([&] { return outcomes.has("Fine"); }, "the outcome of Fine");
    CPPUNIT_ASSERT(!outcomes.has("Hung"));
    release = true;
    waitUntil([&] { return outcomes.has("Hung"); }, "the outcome of Hung");
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(PingThreadsTest);
