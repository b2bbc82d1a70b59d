// Tests dependency order: a module starts only once the modules it comes after answer pings
// (a managed naming service first of all), and a shutdown stops the modules one after the
// other in reverse start order, giving up on one that survives SIGKILL.
#include <cppunit/extensions/HelperMacros.h>

#include "core/supervision/testing/SupervisorRig.h"

using namespace std::chrono_literals;
using rgnav::ExitStatus;
using rgnav::ProcessState;
using rgnav::testing::moduleSpec;
using Actions = std::vector<std::string>;

class SupervisorOrderTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SupervisorOrderTest);
  CPPUNIT_TEST(startWaitsForDependenciesToAnswer);
  CPPUNIT_TEST(managedNamingServiceStartsFirst);
  CPPUNIT_TEST(stopInReverseOrder);
  CPPUNIT_TEST(stopGivesUpOnAProcessThatSurvivesSigkill);
  CPPUNIT_TEST_SUITE_END();

  rgnav::testing::SupervisorRig rig;

  void chain() {
    rig.config.modules = {moduleSpec("C", {"B"}), moduleSpec("B", {"A"}), moduleSpec("A")};
    rig.build();
  }

  void bringUpChain() {
    rig.tick();
    for (const char* name : {"A", "B", "C"}) {
      rig.answer(name, true);
      rig.tick();
    }
  }

 public:
  void startWaitsForDependenciesToAnswer() {
    chain();
    rig.tick();
    CPPUNIT_ASSERT(rig.processes.actions == Actions{"start A"});
    rig.answer("A", false);  // running but not answering yet
    rig.advance(25ms);
    CPPUNIT_ASSERT(rig.processes.actions == Actions{"start A"});
    rig.answer("A", true);
    rig.tick();
    CPPUNIT_ASSERT(rig.processes.actions == (Actions{"start A", "start B"}));
    rig.answer("B", true);
    rig.tick();
    CPPUNIT_ASSERT(rig.processes.actions == (Actions{"start A", "start B", "start C"}));
  }

  void managedNamingServiceStartsFirst() {
    rig.config.naming.managed = true;
    rig.config.modules = {moduleSpec("A")};
    rig.build();
    rig.tick();
    CPPUNIT_ASSERT(rig.processes.actions == Actions{"start NameService"});
    rig.answer("NameService", true);
    rig.tick();
    CPPUNIT_ASSERT(rig.processes.actions == (Actions{"start NameService", "start A"}));
  }

  void stopInReverseOrder() {
    chain();
    bringUpChain();
    rig.processes.actions.clear();
    rig.supervisor->shutDown(rig.now);
    rig.advance(1s);
    CPPUNIT_ASSERT(rig.processes.actions == Actions{"stop C"});
    for (const char* name : {"C", "B", "A"}) {
      CPPUNIT_ASSERT(!rig.supervisor->shutDownComplete());
      rig.processes.exit(name, ExitStatus::signaled(15));
      rig.tick();
      CPPUNIT_ASSERT(rig.state(name) == ProcessState::Stopped);
    }
    CPPUNIT_ASSERT(rig.supervisor->shutDownComplete());
    rig.advance(10s);  // nothing is restarted
    CPPUNIT_ASSERT(rig.processes.actions == (Actions{"stop C", "stop B", "stop A"}));
  }

  void stopGivesUpOnAProcessThatSurvivesSigkill() {
    chain();
    bringUpChain();
    rig.processes.actions.clear();
    rig.supervisor->shutDown(rig.now);
    const auto giveUp = rig.config.modules[0].policy.stopTimeout + rgnav::kKillGrace;
    rig.advance(giveUp);
    CPPUNIT_ASSERT(rig.processes.actions == Actions{"stop C"});
    rig.advance(1ms);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, rig.events.count("C stop-failed"));
    CPPUNIT_ASSERT(rig.processes.actions == (Actions{"stop C", "stop B"}));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(SupervisorOrderTest);
