// Tests the table of module processes: start, reap by name, records for the state file, and
// adoption from records.
#include <cppunit/extensions/HelperMacros.h>
#include <signal.h>

#include "core/common/Errors.h"
#include "watchdog/ProcessTable.h"
#include "watchdog/testing/ProcessGuard.h"
#include "watchdog/testing/TempDir.h"
#include "watchdog/testing/Wait.h"

using rgnav::ExitStatus;
using rgnav::ModuleExit;
using rgnav::ProcessRecord;
using rgnav::ProcessTable;
using rgnav::SpawnSpec;
using rgnav::testing::ProcessGuard;
using rgnav::testing::TempDir;

class ProcessTableTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ProcessTableTest);
  CPPUNIT_TEST(reapsByModuleName);
  CPPUNIT_TEST(adoptsFromRecords);
  CPPUNIT_TEST_SUITE_END();

  TempDir dir_;

  SpawnSpec sleeper() { return {{"sleep", "30"}, {}, "", dir_.file("log")}; }

 public:
  void reapsByModuleName() {
    ProcessTable table;
    const rgnav::ChildProcess& failing = table.start("Failing", {{"/bin/sh", "-c", "exit 3"}, {}, "", dir_.file("log")});
    ProcessGuard failingGuard(failing.pid(), failing.startTime());
    const pid_t failingPid = failing.pid();
    const rgnav::ChildProcess& sleeping = table.start("Sleeping", sleeper());
    ProcessGuard sleepingGuard(sleeping.pid(), sleeping.startTime());
    const std::vector<ProcessRecord> both = table.records();
    CPPUNIT_ASSERT_EQUAL(std::size_t(2), both.size());
    CPPUNIT_ASSERT_EQUAL(std::string("Failing"), both[0].module);
    CPPUNIT_ASSERT_THROW(table.start("Sleeping", sleeper()), rgnav::InvalidArgumentError);

    std::vector<ModuleExit> exits;
    rgnav::testing::waitUntil([&] { return !(exits = table.poll(rgnav::SupervisionClock::now())).empty(); },
                              "the failing module to exit");
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), exits.size());
    CPPUNIT_ASSERT_EQUAL(std::string("Failing"), exits[0].module);
    CPPUNIT_ASSERT_EQUAL(failingPid, exits[0].pid);
    CPPUNIT_ASSERT(exits[0].status == ExitStatus::exited(3));
    CPPUNIT_ASSERT(!table.find("Failing"));
    CPPUNIT_ASSERT_EQUAL(std::size_t(1), table.records().size());

    CPPUNIT_ASSERT(table.find("Sleeping")->signal(SIGKILL));
    rgnav::testing::waitUntil([&] { return !(exits = table.poll(rgnav::SupervisionClock::now())).empty(); },
                              "the sleeping module to die");
    CPPUNIT_ASSERT(exits[0].status == ExitStatus::signaled(SIGKILL));
    CPPUNIT_ASSERT(table.records().empty());
  }
  void adoptsFromRecords() {
    ProcessTable before;
    const rgnav::ChildProcess& running = before.start("Mapper", sleeper());
    ProcessGuard guard(running.pid(), running.startTime());
    const ProcessRecord record = before.records().at(0);
    CPPUNIT_ASSERT_EQUAL(running.startTime(), record.startTime);

    ProcessTable after;
    CPPUNIT_ASSERT(!after.adopt({"Mapper", record.pid, record.startTime + 1}));  // PID reused by another
    CPPUNIT_ASSERT(after.adopt(record));
    CPPUNIT_ASSERT(after.find("Mapper")->adopted());
    CPPUNIT_ASSERT(after.records() == std::vector<ProcessRecord>{record});
    CPPUNIT_ASSERT_THROW(after.adopt(record), rgnav::InvalidArgumentError);
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(ProcessTableTest);
