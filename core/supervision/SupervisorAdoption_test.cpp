// Tests adoption after a watchdog restart: a module whose recorded PID still runs with the
// recorded start time is adopted, not started; a reused PID (another start time), a vanished
// process and a module missing from the state file are started anew.
#include <cppunit/extensions/HelperMacros.h>

#include "core/supervision/testing/SupervisorRig.h"

using rgnav::ProcessRecord;
using rgnav::ProcessState;
using rgnav::testing::moduleSpec;

class SupervisorAdoptionTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(SupervisorAdoptionTest);
  CPPUNIT_TEST(liveModulesAreAdoptedTheOthersStarted);
  CPPUNIT_TEST(adoptedModuleIsADependencyOnceItAnswers);
  CPPUNIT_TEST_SUITE_END();

  rgnav::testing::SupervisorRig rig;

 public:
  void liveModulesAreAdoptedTheOthersStarted() {
    rig.config.modules = {moduleSpec("Live"), moduleSpec("Reused"), moduleSpec("Gone"), moduleSpec("Missing")};
    rig.build();
    rig.processes.machine = {{500, 7}, {501, 9}};
    rig.supervisor->adopt({{"Live", 500, 7}, {"Reused", 501, 8}, {"Gone", 502, 3}, {"Unknown", 503, 4}}, rig.now);
    CPPUNIT_ASSERT(rig.state("Live") == ProcessState::Starting);
    CPPUNIT_ASSERT_EQUAL(pid_t{500}, rig.supervisor->status("Live").pid);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, rig.events.count("Live adopted"));
    CPPUNIT_ASSERT_EQUAL(pid_t{0}, rig.supervisor->status("Reused").pid);

    rig.tick();
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, rig.processes.count("start Live"));
    for (const char* name : {"Reused", "Gone", "Missing"}) {
      CPPUNIT_ASSERT_EQUAL(std::size_t{1}, rig.processes.count(std::string("start ") + name));
      CPPUNIT_ASSERT(rig.state(name) == ProcessState::Starting);
    }
    CPPUNIT_ASSERT(rig.supervisor->status("Reused").pid != 501);
    rig.answer("Live", true);
    CPPUNIT_ASSERT(rig.state("Live") == ProcessState::Running);
    CPPUNIT_ASSERT_EQUAL(pid_t{500}, rig.supervisor->status("Live").pid);
    CPPUNIT_ASSERT_EQUAL(std::uint32_t{0}, rig.supervisor->status("Live").restarts);
  }

  void adoptedModuleIsADependencyOnceItAnswers() {
    rig.config.modules = {moduleSpec("A"), moduleSpec("B", {"A"})};
    rig.build();
    rig.processes.machine = {{500, 7}};
    rig.supervisor->adopt({{"A", 500, 7}}, rig.now);
    rig.tick();
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, rig.processes.count("start B"));
    rig.answer("A", true);
    rig.tick();
    CPPUNIT_ASSERT_EQUAL(std::size_t{0}, rig.processes.count("start A"));
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, rig.processes.count("start B"));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(SupervisorAdoptionTest);
