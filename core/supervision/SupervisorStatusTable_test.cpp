// Tests that the status table agrees with itself and with the processes: an adopted module shows
// the uptime of its process (not of the new watchdog), a module that cannot be spawned shows the
// cause instead of an invented exit code, and RESTARTS counts the restarts the events announce.
#include <cppunit/extensions/HelperMacros.h>

#include "core/supervision/testing/SupervisorRig.h"

using namespace std::chrono_literals;
using rgnav::ProcessState;
using rgnav::testing::moduleSpec;

class SupervisorStatusTableTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SupervisorStatusTableTest);
  CPPUNIT_TEST(adoptedModuleShowsTheUptimeOfItsProcess);
  CPPUNIT_TEST(spawnFailureShowsItsCause);
  CPPUNIT_TEST(restartsCountWhatTheLastEventSays);
  CPPUNIT_TEST_SUITE_END();

  rgnav::testing::SupervisorRig rig;

  bool lastEventHas(const std::string& module, const std::string& text) const {
    return rig.supervisor->status(module).lastEvent.find(text) != std::string::npos;
  }

 public:
  void adoptedModuleShowsTheUptimeOfItsProcess() {
    rig.config.modules = {moduleSpec("Live")};
    rig.config.modules[0].policy.startTimeout = 10s;
    rig.build();
    rig.now += 1h;
    rig.processes.machine = {{500, 7}};
    rig.processes.adoptedAge = 90s;
    rig.supervisor->adopt({{"Live", 500, 7}}, rig.now);
    CPPUNIT_ASSERT(rig.supervisor->status("Live").startedAt == rig.now - 90s);
    // Its start timeout runs from the adoption, not from the process's start.
    rig.advance(5s);
    CPPUNIT_ASSERT(rig.state("Live") == ProcessState::Starting);
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, rig.processes.count("kill Live"));
  }

  void spawnFailureShowsItsCause() {
    rig.config.modules = {moduleSpec("A")};
    rig.build();
    rig.processes.failing = {"A"};
    rig.tick();
    CPPUNIT_ASSERT_MESSAGE(rig.supervisor->status("A").lastEvent,
                           lastEventHas("A", "cannot exec 'rgnav-A': No such file or directory"));
    CPPUNIT_ASSERT(!lastEventHas("A", "code 127"));
  }

  void restartsCountWhatTheLastEventSays() {
    rig.config.modules = {moduleSpec("A")};
    rig.config.modules[0].policy.maxRestarts = 3;
    rig.config.modules[0].policy.backoffInitial = 50ms;
    rig.config.modules[0].policy.backoffMax = 50ms;
    rig.build();
    rig.processes.failing = {"A"};
    rig.tick();
    // The first failure announces a restart: it is counted at once, not when the backoff is over.
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Backoff);
    CPPUNIT_ASSERT(lastEventHas("A", "restart in"));
    CPPUNIT_ASSERT_EQUAL(std::uint32_t{1}, rig.supervisor->status("A").restarts);
    for (int i = 0; i < 10 && rig.state("A") != ProcessState::Fatal; ++i) rig.advance(50ms);
    CPPUNIT_ASSERT(rig.state("A") == ProcessState::Fatal);
    CPPUNIT_ASSERT_MESSAGE(rig.supervisor->status("A").lastEvent, lastEventHas("A", "after 3 restarts"));
    CPPUNIT_ASSERT_EQUAL(std::uint32_t{3}, rig.supervisor->status("A").restarts);
    CPPUNIT_ASSERT(lastEventHas("A", "cannot exec"));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(SupervisorStatusTableTest);
