// integration_watchdog_test: the real rgnav-watchdog supervising playback servers and omniNames
// (module "NameService"): operator stop/start/restart, one-for-one restarts, start order, the
// restart policies, adoption by a new watchdog after SIGKILL, hung detection (SIGSTOP), an
// orderly stop on SIGTERM, and clients finding a server again after the naming service restarts.
// Two-module sets run two playbacks; the second serves its objects as LaserB and BaseB.
#include <cppunit/extensions/HelperMacros.h>
#include <signal.h>

#include <filesystem>
#include <thread>

#include "tests/integration/IntegrationHelpers.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

// Waiting out a time is the scenario here: it proves a stopped module is not started again. Long
// enough for several heartbeats (100 ms) and restart backoffs (50 ms) to have happened.
void settle() { std::this_thread::sleep_for(std::chrono::milliseconds(1000)); }

ClusterModule playbackModule(const std::string& policy = "") {
  return {"LogPlayback", playbackCommand(intelLog()), {"Laser", "Base"}, {}, policy};
}

// PlaybackB is listed first but comes after PlaybackA.
std::vector<ClusterModule> twoModules() {
  return {{"PlaybackB", playbackCommand(intelLog(), {"--laser-object", "LaserB", "--base-object", "BaseB"}),
           {"LaserB", "BaseB"}, {"PlaybackA"}},
          {"PlaybackA", playbackCommand(intelLog()), {"Laser", "Base"}}};
}

void kill(std::int64_t pid, int signal) { CPPUNIT_ASSERT_EQUAL(0, ::kill(static_cast<pid_t>(pid), signal)); }

// The ID of the first scan after `after` that `laser` gets.
DataId firstScanAfter(LaserClient& laser, DataId after) {
  const auto batch = laser.scansSince(after, 100);
  CPPUNIT_ASSERT(!batch.records.empty());
  return batch.records.front().id;
}

// The Laser object answers through a client that resolves it by name now.
void expectLaserServes(TestCluster& cluster, DataId after = 0, const std::string& object = "Laser") {
  LaserClient laser(cluster.clientSettings(), object);
  const auto batch = laser.scansSince(after, 10);
  CPPUNIT_ASSERT_EQUAL(std::size_t{10}, batch.records.size());
  CPPUNIT_ASSERT_EQUAL(after + 1, batch.records.front().id);
}

}  // namespace

class WatchdogIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(WatchdogIntegrationTest);
  CPPUNIT_TEST(testOperatorStopStartRestart);
  CPPUNIT_TEST(testKilledModuleIsRestartedAlone);
  CPPUNIT_TEST(testDependentStartsAfterItsDependencyIsReady);
  CPPUNIT_TEST(testTemporaryModuleKilledStaysStopped);
  CPPUNIT_TEST(testTransientModuleCleanExitStaysStopped);
  CPPUNIT_TEST(testTransientModuleKilledIsRestarted);
  CPPUNIT_TEST(testNewWatchdogAdoptsModulesOfAKilledOne);
  CPPUNIT_TEST(testStoppedProcessIsFoundHungAndRestarted);
  CPPUNIT_TEST(testSigtermStopsEveryProcess);
  CPPUNIT_TEST(testNewClientFindsLaserAfterNamingRestart);
  CPPUNIT_TEST(testServerRebindsInAnEmptyNamingService);
  CPPUNIT_TEST_SUITE_END();

 public:
  void testOperatorStopStartRestart() {
    TestCluster cluster({playbackModule()}, kFastBackoff);
    cluster.start();
    WatchdogClient& watchdog = cluster.watchdog();
    const ModuleProcessInfo first = cluster.describe("LogPlayback");
    const std::uint64_t firstStart = startTimeOf(first.pid);

    watchdog.stopModule("LogPlayback");
    const ModuleProcessInfo stopped = cluster.waitFor("LogPlayback", inState(ProcessState::Stopped), "stopped");
    CPPUNIT_ASSERT_EQUAL(std::int64_t{0}, stopped.pid);
    CPPUNIT_ASSERT(processGone(first.pid, firstStart));
    settle();
    const ModuleProcessInfo still = cluster.describe("LogPlayback");
    CPPUNIT_ASSERT(still.state == ProcessState::Stopped);
    CPPUNIT_ASSERT_EQUAL(stopped.restarts, still.restarts);
    CPPUNIT_ASSERT_EQUAL(std::int64_t{0}, still.pid);

    watchdog.startModule("LogPlayback");
    const ModuleProcessInfo started = cluster.waitFor("LogPlayback", runningAgainAfter(first.pid), "started");
    watchdog.restartModule("LogPlayback");
    const ModuleProcessInfo restarted = cluster.waitFor("LogPlayback", runningAgainAfter(started.pid), "restarted");
    CPPUNIT_ASSERT(restarted.pid != first.pid);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, eventsOf(watchdog, "LogPlayback", "restarted-by-operator").size());
    expectLaserServes(cluster);
  }

  void testKilledModuleIsRestartedAlone() {
    TestCluster cluster(twoModules(), kFastBackoff);
    cluster.start();
    const ModuleProcessInfo a = cluster.describe("PlaybackA");
    const ModuleProcessInfo b = cluster.describe("PlaybackB");
    const ModuleProcessInfo naming = cluster.describe("NameService");

    kill(a.pid, SIGKILL);
    const ModuleProcessInfo a2 = cluster.waitFor("PlaybackA", runningAgainAfter(a.pid), "restarted");
    CPPUNIT_ASSERT_EQUAL(std::uint32_t{1}, a2.restarts);
    CPPUNIT_ASSERT_EQUAL(b.pid, cluster.describe("PlaybackB").pid);
    CPPUNIT_ASSERT_EQUAL(naming.pid, cluster.describe("NameService").pid);

    // The naming service is supervised like any module: only it is restarted.
    kill(naming.pid, SIGKILL);
    cluster.waitFor("NameService", runningAgainAfter(naming.pid), "restarted");
    CPPUNIT_ASSERT_EQUAL(a2.pid, cluster.describe("PlaybackA").pid);
    const ModuleProcessInfo b2 = cluster.describe("PlaybackB");
    CPPUNIT_ASSERT_EQUAL(b.pid, b2.pid);
    CPPUNIT_ASSERT_EQUAL(std::uint32_t{0}, b2.restarts);
    expectLaserServes(cluster, 0, "Laser");
    expectLaserServes(cluster, 0, "LaserB");
  }

  void testDependentStartsAfterItsDependencyIsReady() {
    TestCluster cluster(twoModules(), kFastBackoff);
    cluster.start();
    WatchdogClient& watchdog = cluster.watchdog();
    const auto namingReady = waitForEvent(watchdog, "NameService", "ready");
    const auto aStarted = waitForEvent(watchdog, "PlaybackA", "started");
    const auto aReady = waitForEvent(watchdog, "PlaybackA", "ready");
    const auto bStarted = waitForEvent(watchdog, "PlaybackB", "started");
    CPPUNIT_ASSERT(aStarted.id > namingReady.id);
    CPPUNIT_ASSERT(bStarted.id > aReady.id);
  }

  void testTemporaryModuleKilledStaysStopped() { expectStaysDown("restart: temporary", SIGKILL); }

  void testTransientModuleCleanExitStaysStopped() { expectStaysDown("restart: transient", SIGTERM); }

  void testTransientModuleKilledIsRestarted() {
    TestCluster cluster({playbackModule("restart: transient")}, kFastBackoff);
    cluster.start();
    const ModuleProcessInfo before = cluster.describe("LogPlayback");
    kill(before.pid, SIGKILL);
    const ModuleProcessInfo after = cluster.waitFor("LogPlayback", runningAgainAfter(before.pid), "restarted");
    CPPUNIT_ASSERT_EQUAL(std::uint32_t{1}, after.restarts);
  }

  void testNewWatchdogAdoptsModulesOfAKilledOne() {
    TestCluster cluster({playbackModule()}, kFastBackoff);
    cluster.start();
    const ModuleProcessInfo playback = cluster.describe("LogPlayback");
    const ModuleProcessInfo naming = cluster.describe("NameService");
    LaserClient laser(cluster.clientSettings());
    CPPUNIT_ASSERT_EQUAL(DataId(1), firstScanAfter(laser, 0));

    cluster.stopWatchdog(SIGKILL);
    // Without a watchdog the modules keep serving.
    CPPUNIT_ASSERT_EQUAL(DataId(101), firstScanAfter(laser, 100));

    cluster.start();  // waits for LogPlayback only
    for (const ModuleProcessInfo& before : {playback, naming}) {
      const ModuleProcessInfo now = cluster.waitFor(before.name, isRunning, "running");
      CPPUNIT_ASSERT_EQUAL(before.pid, now.pid);
      const SupervisionEvent adopted = waitForEvent(cluster.watchdog(), before.name, "adopted");
      CPPUNIT_ASSERT(adopted.detail.find(std::to_string(before.pid)) != std::string::npos);
    }

    // An adopted module is no child of the new watchdog, but its death is still noticed.
    kill(playback.pid, SIGKILL);
    const ModuleProcessInfo again = cluster.waitFor("LogPlayback", runningAgainAfter(playback.pid), "restarted");
    CPPUNIT_ASSERT_EQUAL(naming.pid, cluster.describe("NameService").pid);
    CPPUNIT_ASSERT_EQUAL(DataId(201), firstScanAfter(laser, 200));
    CPPUNIT_ASSERT(again.pid != playback.pid);
  }

  void testStoppedProcessIsFoundHungAndRestarted() {
    TestCluster cluster({playbackModule()}, kFastBackoff);
    cluster.start();
    const ModuleProcessInfo before = cluster.describe("LogPlayback");
    const std::uint64_t startTime = startTimeOf(before.pid);
    kill(before.pid, SIGSTOP);
    cluster.waitFor("LogPlayback", runningAgainAfter(before.pid), "restarted");
    const SupervisionEvent hung = waitForEvent(cluster.watchdog(), "LogPlayback", "hung");
    CPPUNIT_ASSERT_MESSAGE(hung.detail, hung.detail.find("pid " + std::to_string(before.pid)) != std::string::npos);
    CPPUNIT_ASSERT(processGone(before.pid, startTime));
    expectLaserServes(cluster);
  }

  void testSigtermStopsEveryProcess() {
    TestCluster cluster(twoModules(), kFastBackoff);
    cluster.start();
    std::vector<std::pair<ModuleProcessInfo, std::uint64_t>> processes;
    for (const ModuleProcessInfo& m : cluster.watchdog().modules()) {
      const ModuleProcessInfo info = cluster.describe(m.name);  // the harness remembers the PID
      processes.emplace_back(info, startTimeOf(info.pid));
    }
    CPPUNIT_ASSERT_EQUAL(std::size_t{3}, processes.size());  // omniNames and two playbacks

    cluster.stopWatchdog(SIGTERM);
    for (const auto& [module, startTime] : processes)
      CPPUNIT_ASSERT_MESSAGE(module.name + " still runs", processGone(module.pid, startTime));
  }

  void testNewClientFindsLaserAfterNamingRestart() {
    TestCluster cluster({playbackModule()}, kFastBackoff);
    cluster.start();
    const ModuleProcessInfo playback = cluster.describe("LogPlayback");
    const ModuleProcessInfo naming = cluster.describe("NameService");
    kill(naming.pid, SIGKILL);
    cluster.waitFor("NameService", runningAgainAfter(naming.pid), "restarted");
    expectLaserServes(cluster);
    CPPUNIT_ASSERT_EQUAL(playback.pid, cluster.describe("LogPlayback").pid);
  }

  // omniNames restarts with its data lost: only the server's own re-registration brings the
  // name back.
  void testServerRebindsInAnEmptyNamingService() {
    TestCluster cluster({playbackModule()}, kFastBackoff);
    cluster.start();
    const ModuleProcessInfo playback = cluster.describe("LogPlayback");
    cluster.watchdog().stopModule("NameService");
    cluster.waitFor("NameService", inState(ProcessState::Stopped), "stopped");
    std::filesystem::remove_all(cluster.dir() + "/run/naming");
    cluster.watchdog().startModule("NameService");
    cluster.waitFor("NameService", isRunning, "running");
    expectLaserServes(cluster);
    CPPUNIT_ASSERT_EQUAL(playback.pid, cluster.describe("LogPlayback").pid);
  }

 private:
  // The module ends by `signal` and, by its restart policy, is not started again.
  static void expectStaysDown(const std::string& policy, int signal) {
    TestCluster cluster({playbackModule(policy)}, kFastBackoff);
    cluster.start();
    const ModuleProcessInfo before = cluster.describe("LogPlayback");
    kill(before.pid, signal);
    cluster.waitFor("LogPlayback", inState(ProcessState::Stopped), "stopped");
    settle();
    const ModuleProcessInfo after = cluster.describe("LogPlayback");
    CPPUNIT_ASSERT(after.state == ProcessState::Stopped);
    CPPUNIT_ASSERT_EQUAL(std::uint32_t{0}, after.restarts);
    CPPUNIT_ASSERT_EQUAL(std::int64_t{0}, after.pid);
    CPPUNIT_ASSERT_EQUAL(std::size_t{1}, eventsOf(cluster.watchdog(), "LogPlayback", "exited").size());
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(WatchdogIntegrationTest);
