// Tests /proc/<pid>/stat reading: start time identifies a process, odd command names parse (and
// the fields after them: the process group), zombies and missing processes are not alive, and a
// process's age comes from its start time.
#include <cppunit/extensions/HelperMacros.h>
#include <time.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <limits>

#include "watchdog/ChildProcess.h"
#include "watchdog/ProcStat.h"
#include "watchdog/testing/ProcessGuard.h"
#include "watchdog/testing/TempDir.h"
#include "watchdog/testing/Wait.h"

using rgnav::ChildProcess;
using rgnav::readProcStat;
using rgnav::testing::ProcessGuard;
using rgnav::testing::TempDir;

namespace {

// The clock /proc/<pid>/stat counts start times in (since Linux 5.3: boot time, in clock ticks).
std::uint64_t ticksSinceBoot() {
  timespec now{};
  clock_gettime(CLOCK_BOOTTIME, &now);
  const auto ticksPerSecond = static_cast<std::uint64_t>(sysconf(_SC_CLK_TCK));
  return static_cast<std::uint64_t>(now.tv_sec) * ticksPerSecond +
         static_cast<std::uint64_t>(now.tv_nsec) * ticksPerSecond / 1000000000u;
}

}  // namespace

class ProcStatTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ProcStatTest);
  CPPUNIT_TEST(readsOwnProcess);
  CPPUNIT_TEST(startTimeIsStableAndDiffersForNewProcess);
  CPPUNIT_TEST(parsesCommandNameWithParenthesisAndSpace);
  CPPUNIT_TEST(ageCountsFromTheStartTime);
  CPPUNIT_TEST(missingProcessIsNotAlive);
  CPPUNIT_TEST(zombieIsNotAlive);
  CPPUNIT_TEST_SUITE_END();

  TempDir dir_;

  ChildProcess startSleep(const std::string& program = "sleep") {
    return ChildProcess::start({{program, "30"}, {}, "", dir_.file("log")});
  }

 public:
  void readsOwnProcess() {
    const std::optional<rgnav::ProcStat> self = readProcStat(getpid());
    CPPUNIT_ASSERT(self);
    CPPUNIT_ASSERT_EQUAL('R', self->state);
    CPPUNIT_ASSERT(rgnav::isProcessAlive(getpid(), self->startTime));
  }
  void startTimeIsStableAndDiffersForNewProcess() {
    ChildProcess first = startSleep();
    ProcessGuard firstGuard(first.pid(), first.startTime());
    CPPUNIT_ASSERT_EQUAL(first.startTime(), readProcStat(first.pid())->startTime);
    CPPUNIT_ASSERT_EQUAL(first.startTime(), readProcStat(first.pid())->startTime);
    // Start times count clock ticks since boot: wait for two more so the next process cannot share one.
    rgnav::testing::waitUntil([&] { return ticksSinceBoot() >= first.startTime() + 2; }, "two clock ticks to pass");
    ChildProcess second = startSleep();
    ProcessGuard secondGuard(second.pid(), second.startTime());
    CPPUNIT_ASSERT(first.startTime() < second.startTime());
    CPPUNIT_ASSERT(!rgnav::isProcessAlive(first.pid(), second.startTime()));
  }
  void parsesCommandNameWithParenthesisAndSpace() {
    const std::string program = dir_.file("we) ird (x");
    std::filesystem::copy_file("/bin/sleep", program);
    ChildProcess p = startSleep(program);
    ProcessGuard guard(p.pid(), p.startTime());
    rgnav::testing::waitUntil([&] { return readProcStat(p.pid())->state == 'S'; }, "the program to sleep");
    CPPUNIT_ASSERT(rgnav::isProcessAlive(p.pid(), p.startTime()));
    CPPUNIT_ASSERT_EQUAL(p.pid(), readProcStat(p.pid())->group);  // it leads its own process group
  }
  void ageCountsFromTheStartTime() {
    const std::optional<rgnav::ProcStat> self = readProcStat(getpid());
    const auto ticksPerSecond = static_cast<std::uint64_t>(sysconf(_SC_CLK_TCK));
    CPPUNIT_ASSERT(rgnav::processAge(self->startTime) >= std::chrono::nanoseconds(0));
    // A process that started 10 s earlier is 10 s older (give or take the clock tick and the reads).
    const double older = std::chrono::duration<double>(rgnav::processAge(self->startTime - 10 * ticksPerSecond) -
                                                       rgnav::processAge(self->startTime)).count();
    CPPUNIT_ASSERT_DOUBLES_EQUAL(10.0, older, 0.5);
  }
  void missingProcessIsNotAlive() {
    const pid_t impossible = std::numeric_limits<pid_t>::max();
    CPPUNIT_ASSERT(!readProcStat(impossible));
    CPPUNIT_ASSERT(!rgnav::isProcessAlive(impossible, 0));
  }
  void zombieIsNotAlive() {
    ChildProcess p = ChildProcess::start({{"/bin/true"}, {}, "", dir_.file("log")});
    ProcessGuard guard(p.pid(), p.startTime());  // reaps the zombie at the end
    rgnav::testing::waitUntil([&] { return readProcStat(p.pid())->state == 'Z'; }, "a zombie");
    CPPUNIT_ASSERT(!rgnav::isProcessAlive(p.pid(), p.startTime()));
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(ProcStatTest);
