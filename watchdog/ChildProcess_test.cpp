// Tests spawning and supervising real processes: exit codes, signals, exec failures, stop with
// SIGKILL escalation, output redirection, process groups and adoption. Every process started
// here is killed by PID at the end of its test, also when the test fails.
#include <cppunit/extensions/HelperMacros.h>
#include <signal.h>
#include <unistd.h>

#include "core/common/Errors.h"
#include "watchdog/ChildProcess.h"
#include "watchdog/ProcStat.h"
#include "watchdog/ProcessError.h"
#include "watchdog/testing/ProcessGuard.h"
#include "watchdog/testing/TempDir.h"
#include "watchdog/testing/Wait.h"

using namespace std::chrono_literals;
using rgnav::ChildProcess;
using rgnav::ExitStatus;
using rgnav::SpawnSpec;
using rgnav::testing::ProcessGuard;
using rgnav::testing::readFile;
using rgnav::testing::TempDir;
using rgnav::testing::waitForExit;
using rgnav::testing::waitForText;

namespace {

SpawnSpec shell(const std::string& script, const std::string& logFile) {
  return SpawnSpec{{"/bin/sh", "-c", script}, {}, "", logFile};
}

std::string startError(const SpawnSpec& spec) {
  try {
    ChildProcess p = ChildProcess::start(spec);
    ProcessGuard guard(p.pid(), p.startTime());
  } catch (const rgnav::ProcessError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

class ChildProcessTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ChildProcessTest);
  CPPUNIT_TEST(reportsExitCode);
  CPPUNIT_TEST(reportsKillingSignal);
  CPPUNIT_TEST(execFailureIsTypedError);
  CPPUNIT_TEST(badWorkingDirectoryIsTypedError);
  CPPUNIT_TEST(badLogFileIsFileError);
  CPPUNIT_TEST(outputEnvironmentAndDirectory);
  CPPUNIT_TEST(runsInOwnProcessGroup);
  CPPUNIT_TEST(stopEndsCooperativeProcessWithSigterm);
  CPPUNIT_TEST(stopEscalatesToSigkill);
  CPPUNIT_TEST(endedProcessIsNeverSignalled);
  CPPUNIT_TEST(adoptsOnlyMatchingStartTime);
  CPPUNIT_TEST(adoptedOwnChildKeepsExitStatus);
  CPPUNIT_TEST(adoptedForeignProcessEndsAsLost);
  CPPUNIT_TEST_SUITE_END();

  TempDir dir_;

 public:
  void reportsExitCode() {
    ChildProcess p = ChildProcess::start(shell("exit 3", dir_.file("log")));
    ProcessGuard guard(p.pid(), p.startTime());
    const ExitStatus status = waitForExit(p);
    CPPUNIT_ASSERT(status.kind() == ExitStatus::Kind::Exited);
    CPPUNIT_ASSERT_EQUAL(3, status.code());
    CPPUNIT_ASSERT(p.poll(rgnav::SupervisionClock::now()) == ExitStatus::exited(3));  // stays known
  }
  void reportsKillingSignal() {
    ChildProcess p = ChildProcess::start({{"sleep", "30"}, {}, "", dir_.file("log")});
    ProcessGuard guard(p.pid(), p.startTime());
    CPPUNIT_ASSERT(!p.poll(rgnav::SupervisionClock::now()));
    CPPUNIT_ASSERT(p.signal(SIGKILL));
    const ExitStatus status = waitForExit(p);
    CPPUNIT_ASSERT(status.kind() == ExitStatus::Kind::Signaled);
    CPPUNIT_ASSERT_EQUAL(SIGKILL, status.signal());
  }
  void execFailureIsTypedError() {
    const std::string absolute = startError({{"/nonexistent/rgnav-no-such-server"}, {}, "", dir_.file("log")});
    CPPUNIT_ASSERT_MESSAGE(absolute, absolute.find("cannot exec '/nonexistent/rgnav-no-such-server': No such file "
                                                   "or directory") != std::string::npos);
    const std::string searched = startError({{"rgnav-no-such-server"}, {}, "", dir_.file("log")});
    CPPUNIT_ASSERT_MESSAGE(searched, searched.find("cannot exec 'rgnav-no-such-server'") != std::string::npos);
    CPPUNIT_ASSERT_THROW(ChildProcess::start({{}, {}, "", dir_.file("log")}), rgnav::InvalidArgumentError);
  }
  void badWorkingDirectoryIsTypedError() {
    const std::string message = startError({{"/bin/true"}, {}, dir_.file("missing"), dir_.file("log")});
    CPPUNIT_ASSERT_MESSAGE(message, message.find("working directory") != std::string::npos);
  }
  void badLogFileIsFileError() {
    CPPUNIT_ASSERT_THROW(ChildProcess::start(shell("exit 0", dir_.file("missing/log"))), rgnav::FileError);
  }
  void outputEnvironmentAndDirectory() {
    const std::string log = dir_.file("module.log");
    { std::ofstream(log) << "earlier run\n"; }
    SpawnSpec spec = shell("echo out; echo err >&2; echo \"foo=$FOO\"; pwd; "
                           "if read line; then echo stdin=data; else echo stdin=eof; fi",
                           log);
    spec.env = {{"FOO", "bar"}};
    spec.cwd = dir_.path();
    ChildProcess p = ChildProcess::start(spec);
    ProcessGuard guard(p.pid(), p.startTime());
    CPPUNIT_ASSERT(waitForExit(p) == ExitStatus::exited(0));
    const std::string expected = "earlier run\nout\nerr\nfoo=bar\n" + dir_.path() + "\nstdin=eof\n";
    CPPUNIT_ASSERT_EQUAL(expected, readFile(log));
  }
  void runsInOwnProcessGroup() {
    ChildProcess p = ChildProcess::start({{"sleep", "30"}, {}, "", dir_.file("log")});
    ProcessGuard guard(p.pid(), p.startTime());
    CPPUNIT_ASSERT_EQUAL(p.pid(), getpgid(p.pid()));
  }
  void stopEndsCooperativeProcessWithSigterm() {
    ChildProcess p = ChildProcess::start({{"sleep", "30"}, {}, "", dir_.file("log")});
    ProcessGuard guard(p.pid(), p.startTime());
    CPPUNIT_ASSERT(p.stop(10s) == ExitStatus::signaled(SIGTERM));
  }
  void stopEscalatesToSigkill() {
    const std::string log = dir_.file("log");
    ChildProcess p = ChildProcess::start(shell("trap '' TERM; echo ready; exec sleep 30", log));
    ProcessGuard guard(p.pid(), p.startTime());
    waitForText(log, "ready");  // SIGTERM is ignored from here on, also after exec
    CPPUNIT_ASSERT(p.stop(200ms) == ExitStatus::signaled(SIGKILL));
  }
  void endedProcessIsNeverSignalled() {
    ChildProcess p = ChildProcess::start(shell("exit 0", dir_.file("log")));
    ProcessGuard guard(p.pid(), p.startTime());
    waitForExit(p);
    CPPUNIT_ASSERT(!p.signal(SIGKILL));
    CPPUNIT_ASSERT(!p.signalGroup(SIGKILL));
    CPPUNIT_ASSERT(p.stop(1s) == ExitStatus::exited(0));
  }
  void adoptsOnlyMatchingStartTime() {
    ChildProcess p = ChildProcess::start({{"sleep", "30"}, {}, "", dir_.file("log")});
    ProcessGuard guard(p.pid(), p.startTime());
    CPPUNIT_ASSERT(!ChildProcess::adopt(p.pid(), p.startTime() + 1));
    CPPUNIT_ASSERT(!ChildProcess::adopt(1, p.startTime()));
    const std::optional<ChildProcess> adopted = ChildProcess::adopt(p.pid(), p.startTime());
    CPPUNIT_ASSERT(adopted && adopted->adopted());
  }
  // A watchdog that re-executed itself is still the parent: the real status is reaped.
  void adoptedOwnChildKeepsExitStatus() {
    ChildProcess p = ChildProcess::start({{"sleep", "30"}, {}, "", dir_.file("log")});
    ProcessGuard guard(p.pid(), p.startTime());
    std::optional<ChildProcess> adopted = ChildProcess::adopt(p.pid(), p.startTime());
    CPPUNIT_ASSERT(adopted);
    CPPUNIT_ASSERT(adopted->signal(SIGKILL));
    CPPUNIT_ASSERT(waitForExit(*adopted) == ExitStatus::signaled(SIGKILL));
  }
  // A process that is not our child (here: a grandchild, reaped by its own parent) is judged by
  // /proc; dead or zombie, it ends as lost.
  void adoptedForeignProcessEndsAsLost() {
    const std::string log = dir_.file("log");
    ChildProcess parent = ChildProcess::start(shell("sleep 30 & echo \"pid=$!\"; wait", log));
    ProcessGuard parentGuard(parent.pid(), parent.startTime());
    waitForText(log, "\n");
    const pid_t grandchild = std::stoi(readFile(log).substr(readFile(log).find("pid=") + 4));
    const std::optional<rgnav::ProcStat> stat = rgnav::readProcStat(grandchild);
    CPPUNIT_ASSERT(stat);
    ProcessGuard grandchildGuard(grandchild, stat->startTime);
    std::optional<ChildProcess> adopted = ChildProcess::adopt(grandchild, stat->startTime);
    CPPUNIT_ASSERT(adopted);
    CPPUNIT_ASSERT(!adopted->poll(rgnav::SupervisionClock::now()));
    CPPUNIT_ASSERT(adopted->signal(SIGKILL));
    CPPUNIT_ASSERT(waitForExit(*adopted) == ExitStatus::lost());
    CPPUNIT_ASSERT(waitForExit(parent) == ExitStatus::exited(0));
  }
};
CPPUNIT_TEST_SUITE_REGISTRATION(ChildProcessTest);
