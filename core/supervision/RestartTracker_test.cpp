// Tests restart decisions: policies, operator stops, restart intensity in a sliding window,
// FATAL, and the backoff arithmetic.
#include <cppunit/extensions/HelperMacros.h>

#include "core/supervision/RestartTracker.h"

using namespace std::chrono_literals;
using rgnav::ExitInfo;
using rgnav::ExitStatus;
using rgnav::RestartPolicy;
using rgnav::RestartTracker;
using Action = rgnav::RestartDecision::Action;

namespace {

const rgnav::SupervisionClock::time_point t0{};

rgnav::ModulePolicy policy(RestartPolicy restart, int maxRestarts = 100, std::chrono::nanoseconds window = 60s) {
  rgnav::ModulePolicy p;
  p.restart = restart;
  p.maxRestarts = maxRestarts;
  p.restartWindow = window;
  p.backoffInitial = 50ms;
  p.backoffMax = 2s;
  return p;
}

Action actionFor(RestartPolicy restart, const ExitInfo& exit) {
  RestartTracker tracker("M", policy(restart));
  return tracker.onExit(exit, t0).action;
}

const ExitInfo kClean{ExitStatus::exited(0)};
const ExitInfo kFailed{ExitStatus::exited(3)};
const ExitInfo kKilled{ExitStatus::signaled(9)};
const ExitInfo kLost{ExitStatus::lost()};

}  // namespace

class RestartTrackerTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(RestartTrackerTest);
  CPPUNIT_TEST(exitStatusClassifiesAndDescribes);
  CPPUNIT_TEST(permanentRestartsEveryExit);
  CPPUNIT_TEST(transientRestartsOnlyAbnormalExits);
  CPPUNIT_TEST(temporaryNeverRestarts);
  CPPUNIT_TEST(operatorStopIsNeverRestarted);
  CPPUNIT_TEST(intensityLimitMakesFatal);
  CPPUNIT_TEST(windowSlides);
  CPPUNIT_TEST(zeroMaxRestartsFailsAtOnce);
  CPPUNIT_TEST(backoffDoublesUntilCap);
  CPPUNIT_TEST(readyRunRestartsWithoutDelayAndResetsBackoff);
  CPPUNIT_TEST(resetClearsFatal);
  CPPUNIT_TEST_SUITE_END();

 public:
  void exitStatusClassifiesAndDescribes() {
    CPPUNIT_ASSERT(!ExitStatus::exited(0).abnormal());
    CPPUNIT_ASSERT(ExitStatus::exited(3).abnormal());
    CPPUNIT_ASSERT(ExitStatus::signaled(9).abnormal());
    CPPUNIT_ASSERT(ExitStatus::lost().abnormal());
    CPPUNIT_ASSERT_EQUAL(-1, ExitStatus::signaled(9).code());
    CPPUNIT_ASSERT_EQUAL(0, ExitStatus::exited(3).signal());
    CPPUNIT_ASSERT_EQUAL(std::string("exited with code 3"), ExitStatus::exited(3).describe());
    CPPUNIT_ASSERT_EQUAL(std::string("killed by signal 9"), ExitStatus::signaled(9).describe());
  }
  void permanentRestartsEveryExit() {
    for (const ExitInfo& exit : {kClean, kFailed, kKilled, kLost}) {
      CPPUNIT_ASSERT(actionFor(RestartPolicy::Permanent, exit) == Action::Restart);
    }
  }
  void transientRestartsOnlyAbnormalExits() {
    CPPUNIT_ASSERT(actionFor(RestartPolicy::Transient, kClean) == Action::StayDown);
    for (const ExitInfo& exit : {kFailed, kKilled, kLost}) {
      CPPUNIT_ASSERT(actionFor(RestartPolicy::Transient, exit) == Action::Restart);
    }
  }
  void temporaryNeverRestarts() {
    for (const ExitInfo& exit : {kClean, kFailed, kKilled, kLost}) {
      CPPUNIT_ASSERT(actionFor(RestartPolicy::Temporary, exit) == Action::StayDown);
    }
  }
  void operatorStopIsNeverRestarted() {
    RestartTracker tracker("Mapper", policy(RestartPolicy::Permanent));
    const rgnav::RestartDecision d = tracker.onExit({ExitStatus::signaled(15), true}, t0);
    CPPUNIT_ASSERT(d.action == Action::StayDown);
    CPPUNIT_ASSERT_MESSAGE(d.reason, d.reason.find("Mapper: stopped by operator") == 0);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(0), tracker.restartsTotal());
  }
  void intensityLimitMakesFatal() {
    RestartTracker tracker("Mapper", policy(RestartPolicy::Permanent, 3, 10s));
    for (int i = 0; i < 3; ++i) {
      CPPUNIT_ASSERT(tracker.onExit(kKilled, t0 + i * 1s).action == Action::Restart);
    }
    CPPUNIT_ASSERT_EQUAL(3, tracker.restartsInWindow(t0 + 3s));
    const rgnav::RestartDecision fatal = tracker.onExit(kKilled, t0 + 3s);
    CPPUNIT_ASSERT(fatal.action == Action::Fatal);
    CPPUNIT_ASSERT(tracker.fatal());
    CPPUNIT_ASSERT_MESSAGE(fatal.reason, fatal.reason.find("Mapper: FATAL") == 0);
    CPPUNIT_ASSERT_MESSAGE(fatal.reason, fatal.reason.find("3 restarts within 10 s") != std::string::npos);
    // Stays down, even long after the window.
    CPPUNIT_ASSERT(tracker.onExit(kKilled, t0 + 1000s).action == Action::Fatal);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(3), tracker.restartsTotal());
  }
  void windowSlides() {
    RestartTracker tracker("M", policy(RestartPolicy::Permanent, 2, 10s));
    CPPUNIT_ASSERT(tracker.onExit(kFailed, t0).action == Action::Restart);
    CPPUNIT_ASSERT(tracker.onExit(kFailed, t0 + 5s).action == Action::Restart);
    CPPUNIT_ASSERT_EQUAL(2, tracker.restartsInWindow(t0 + 9s));
    CPPUNIT_ASSERT_EQUAL(1, tracker.restartsInWindow(t0 + 10s));  // the restart at t0 has left
    CPPUNIT_ASSERT(tracker.onExit(kFailed, t0 + 10s).action == Action::Restart);
    CPPUNIT_ASSERT(tracker.onExit(kFailed, t0 + 12s).action == Action::Fatal);
    CPPUNIT_ASSERT_EQUAL(std::uint64_t(3), tracker.restartsTotal());
  }
  void zeroMaxRestartsFailsAtOnce() {
    RestartTracker tracker("M", policy(RestartPolicy::Permanent, 0));
    CPPUNIT_ASSERT(tracker.onExit(kFailed, t0).action == Action::Fatal);
  }
  void backoffDoublesUntilCap() {
    RestartTracker tracker("M", policy(RestartPolicy::Permanent));
    const std::vector<std::chrono::milliseconds> expected{50ms, 100ms, 200ms, 400ms, 800ms, 1600ms, 2000ms, 2000ms};
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const rgnav::RestartDecision d = tracker.onExit(kFailed, t0 + i * 1s);
      CPPUNIT_ASSERT(d.action == Action::Restart);
      CPPUNIT_ASSERT_EQUAL(std::chrono::nanoseconds(expected[i]).count(), d.delay.count());
    }
  }
  void readyRunRestartsWithoutDelayAndResetsBackoff() {
    RestartTracker tracker("M", policy(RestartPolicy::Permanent));
    tracker.onExit(kFailed, t0);
    tracker.onExit(kFailed, t0 + 1s);  // 100 ms
    tracker.onReady();
    CPPUNIT_ASSERT(tracker.onExit(kKilled, t0 + 2s).delay == 0ms);
    CPPUNIT_ASSERT(tracker.onExit(kKilled, t0 + 3s).delay == 50ms);  // that run never got ready
    CPPUNIT_ASSERT(tracker.onExit(kKilled, t0 + 4s).delay == 100ms);
  }
  void resetClearsFatal() {
    RestartTracker tracker("M", policy(RestartPolicy::Permanent, 1));
    tracker.onExit(kFailed, t0);
    CPPUNIT_ASSERT(tracker.onExit(kFailed, t0).action == Action::Fatal);
    tracker.reset();
    CPPUNIT_ASSERT(!tracker.fatal());
    CPPUNIT_ASSERT_EQUAL(0, tracker.restartsInWindow(t0));
    const rgnav::RestartDecision d = tracker.onExit(kFailed, t0);
    CPPUNIT_ASSERT(d.action == Action::Restart);
    CPPUNIT_ASSERT(d.delay == 50ms);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(RestartTrackerTest);
