// Tests restarts: restart intensity (max_restarts within restart_window makes a module FATAL
// while the others keep running), exponential capped backoff for a module that fails before
// it ever answered, and the transient and temporary policies.
#include <cppunit/extensions/HelperMacros.h>

#include "core/supervision/testing/SupervisorRig.h"

using namespace std::chrono_literals;
using rgnav::ExitStatus;
using rgnav::ProcessState;
using rgnav::RestartPolicy;
using rgnav::testing::moduleSpec;

class SupervisorRestartTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SupervisorRestartTest);
  CPPUNIT_TEST(restartIntensityMakesFatalOthersKeepRunning);
  CPPUNIT_TEST(backoffBeforeFirstReadyGrowsAndIsCapped);
  CPPUNIT_TEST(transientRestartsOnlyAfterAbnormalExit);
  CPPUNIT_TEST(temporaryIsNeverRestarted);
  CPPUNIT_TEST_SUITE_END();

  rgnav::testing::SupervisorRig rig;

 public:
  void restartIntensityMakesFatalOthersKeepRunning() {
    rig.config.modules = {moduleSpec("A"), moduleSpec("B")};
    rig.config.modules[0].policy.maxRestarts = 3;
    rig.build();
    rig.bringUp();
    for (int restart = 1; restart <= 3; ++restart) {
      rig.processes.exit("A", ExitStatus::exited(1));
      rig.tick();
      CPPUNIT_ASSERT(rig.state("A") == ProcessState::Starting);
      rig.answer("A", true);
      rig.advance(1s);
      rig.answer("A", true);
      rig.answer("B", true);
    }
    rig.processes.exit("A", ExitStatus::exited(1));
    rig.tick();
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Fatal);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, rig.events.count("A FATAL"));
    rig.advance(120s);
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Fatal);
    CPPUNIT_ASSERT_EQUAL(std::size_t{4}, rig.processes.count("start A"));

    CPPUNIT_ASSERT(rig.state("B") == ProcessState::Running);
    rig.answer("B", true);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, rig.processes.count("start B"));
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, rig.processes.count("kill B") + rig.processes.count("stop B"));
  }

  void backoffBeforeFirstReadyGrowsAndIsCapped() {
    rig.config.modules = {moduleSpec("A")};
    rig.config.modules[0].policy.backoffInitial = 50ms;
    rig.config.modules[0].policy.backoffMax = 300ms;
    rig.build();
    rig.tick();
    std::size_t starts = 1;
    for (const auto delay : {50ms, 100ms, 200ms, 300ms, 300ms}) {
      rig.processes.exit("A", ExitStatus::exited(1));
      rig.tick();
      CPPUNIT_ASSERT(rig.state("A") == ProcessState::Backoff);
      rig.advance(delay - 1ms);
      CPPUNIT_ASSERT(rig.state("A") == ProcessState::Backoff);
      CPPUNIT_ASSERT_EQUAL(starts, rig.processes.count("start A"));
      rig.advance(1ms);
      CPPUNIT_ASSERT(rig.state("A") == ProcessState::Starting);
      CPPUNIT_ASSERT_EQUAL(++starts, rig.processes.count("start A"));
    }
    // Once it has answered, an exit is restarted without delay.
    rig.answer("A", true);  // the answer of a former process does not count
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Starting);
    rig.tick();
    rig.answer("A", true);
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Running);
    rig.processes.exit("A", ExitStatus::exited(1));
    rig.tick();
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Starting);
    CPPUNIT_ASSERT_EQUAL(++starts, rig.processes.count("start A"));
  }

  void transientRestartsOnlyAfterAbnormalExit() {
    rig.config.modules = {moduleSpec("Clean"), moduleSpec("Crash")};
    for (auto& m : rig.config.modules) m.policy.restart = RestartPolicy::Transient;
    rig.build();
    rig.bringUp();
    rig.processes.exit("Clean", ExitStatus::exited(0));
    rig.processes.exit("Crash", ExitStatus::signaled(11));
    rig.tick();
    CPPUNIT_ASSERT(rig.state("Clean") == ProcessState::Stopped);
    CPPUNIT_ASSERT(rig.state("Crash") == ProcessState::Starting);
    rig.advance(5s);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, rig.processes.count("start Clean"));
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, rig.processes.count("start Crash"));
  }

  void temporaryIsNeverRestarted() {
    rig.config.modules = {moduleSpec("A")};
    rig.config.modules[0].policy.restart = RestartPolicy::Temporary;
    rig.build();
    rig.bringUp();
    rig.processes.exit("A", ExitStatus::signaled(11));
    rig.tick();
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Stopped);
    rig.advance(10s);
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Stopped);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, rig.processes.count("start A"));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(SupervisorRestartTest);
