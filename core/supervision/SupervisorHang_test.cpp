// Tests hang detection: pings every heartbeat period, two missed pings in a row while running
// kill the process group and restart the module, one missed ping does nothing, and a module
// that never answers within its start timeout is hung too.
#include <cppunit/extensions/HelperMacros.h>

#include "core/supervision/testing/SupervisorRig.h"

using namespace std::chrono_literals;
using rgnav::ExitStatus;
using rgnav::ProcessState;
using rgnav::testing::moduleSpec;

class SupervisorHangTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SupervisorHangTest);
  CPPUNIT_TEST(pingsEveryHeartbeatPeriod);
  CPPUNIT_TEST(twoMissedPingsKillAndRestart);
  CPPUNIT_TEST(oneMissedPingDoesNothing);
  CPPUNIT_TEST(noAnswerWithinStartTimeoutIsHung);
  CPPUNIT_TEST_SUITE_END();

  rgnav::testing::SupervisorRig rig;

 public:
  void setUp() override {
    rig.config.modules = {moduleSpec("A")};
    rig.build();
    rig.bringUp();
  }

  void pingsEveryHeartbeatPeriod() {
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Running);
    rig.advance(99ms);
    CPPUNIT_ASSERT(rig.probe.outstanding.empty());
    rig.advance(1ms);
    rig.answer("A", true);
    rig.advance(100ms);
    rig.answer("A", true);
  }

  void twoMissedPingsKillAndRestart() {
    rig.advance(100ms);
    rig.answer("A", false);
    rig.tick();  // the second ping goes out at once
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, rig.processes.count("kill A"));
    rig.answer("A", false);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, rig.processes.count("kill A"));
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Hung);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, rig.events.count("A hung"));

    rig.processes.exit("A", ExitStatus::signaled(9));
    rig.tick();
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Starting);
    CPPUNIT_ASSERT_EQUAL(std::size_t{2}, rig.processes.count("start A"));
    CPPUNIT_ASSERT_EQUAL(rig.processes.table.at("A"), rig.supervisor->status("A").pid);
    CPPUNIT_ASSERT_EQUAL(std::uint32_t{1}, rig.supervisor->status("A").restarts);
  }

  void oneMissedPingDoesNothing() {
    for (int round = 0; round < 3; ++round) {
      rig.advance(100ms);
      rig.answer("A", false);
      rig.tick();
      rig.answer("A", true);  // the miss count starts over
    }
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Running);
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, rig.processes.count("kill A"));
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, rig.events.count("A hung"));
  }

  void noAnswerWithinStartTimeoutIsHung() {
    rig.processes.exit("A", ExitStatus::exited(1));
    rig.tick();
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Starting);
    const auto startTimeout = rig.config.modules[0].policy.startTimeout;
    const auto startedAt = rig.now;
    // Unanswered pings while starting are no hang: the start timeout decides.
    while (rig.now + 25ms <= startedAt + startTimeout) {
      rig.answer("A", false);
      rig.advance(25ms);
    }
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Starting);
    rig.advance(startedAt + startTimeout - rig.now);
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Starting);
    rig.advance(1ms);
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Hung);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, rig.processes.count("kill A"));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(SupervisorHangTest);
