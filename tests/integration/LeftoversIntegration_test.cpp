// integration_leftovers_test: a set's processes as found without its watchdog, and pings that
// must come from the module's own process. After the watchdog is SIGKILLed, its modules are found
// from the state file (PID + start time), hold their own ports (which a start after a deleted
// run dir must refuse, naming them) and are stopped in reverse order. A module whose port is
// answered by a process outside its process group (a port clash) never counts as ready.
#include <cppunit/extensions/HelperMacros.h>
#include <signal.h>

#include <algorithm>
#include <filesystem>

#include "tests/integration/IntegrationHelpers.h"
#include "watchdog/PortHolder.h"
#include "watchdog/SetLeftovers.h"
#include "watchdog/SetLoading.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

ClusterModule playbackModule() { return {"LogPlayback", playbackCommand(intelLog()), {"Laser", "Base"}}; }

// A module whose process never binds its port: it starts a playback in a session of its own (so
// outside the module's process group) on the module's endpoint, then sleeps. The playback answers
// every ping sent to the module's port, as another set's server would after a port clash.
ClusterModule impostorModule() {
  std::string script = "setsid";
  for (const std::string& word : playbackCommand(intelLog())) script.append(" ").append(word);
  script.append(" $@ & exec sleep 600");
  return {"Impostor",
          {"/bin/sh", "-c", script, "sh"},
          {"Laser", "Base"},
          {},
          "restart: temporary\n    start_timeout_s: 1"};
}

// Kills, by PID, the process that listens on a port, if its command line names that endpoint.
struct PortHolderKiller {
  int port;
  ~PortHolderKiller() {
    const std::optional<PortHolder> holder = findPortHolder({"127.0.0.1", port});
    std::string endpoint(1, ':');
    endpoint.append(std::to_string(port));
    if (holder && holder->pid > 1 && holder->command.find(endpoint) != std::string::npos)
      ::kill(holder->pid, SIGKILL);
  }
};

std::vector<std::string> moduleNames(const std::vector<LeftoverModule>& leftovers) {
  std::vector<std::string> names;
  for (const LeftoverModule& m : leftovers) names.push_back(m.record.module);
  return names;
}

}  // namespace

class LeftoversIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(LeftoversIntegrationTest);
  CPPUNIT_TEST(testModulesOfAKilledWatchdogAreFoundAndStopped);
  CPPUNIT_TEST(testAnswerFromAnotherProcessGroupIsNotReady);
  CPPUNIT_TEST_SUITE_END();

 public:
  void testModulesOfAKilledWatchdogAreFoundAndStopped() {
    TestCluster cluster({playbackModule()});
    cluster.start();
    const ModuleProcessInfo playback = cluster.describe("LogPlayback");
    const ModuleProcessInfo naming = cluster.describe("NameService");
    const std::uint64_t playbackStart = startTimeOf(playback.pid);
    const std::uint64_t namingStart = startTimeOf(naming.pid);
    cluster.stopWatchdog(SIGKILL);
    const SetConfig set = loadSet(cluster.setFile(), cluster.dir());

    const std::vector<LeftoverModule> leftovers = leftoverModules(set);
    CPPUNIT_ASSERT((moduleNames(leftovers) == std::vector<std::string>{"NameService", "LogPlayback"}));
    CPPUNIT_ASSERT_EQUAL(static_cast<pid_t>(playback.pid), leftovers[1].record.pid);
    CPPUNIT_ASSERT(leftovers[1].age > std::chrono::nanoseconds(0));
    // They hold their own ports: a new watchdog adopts them, so nothing is in the way ...
    CPPUNIT_ASSERT(heldPorts(set, leftovers).empty());
    // ... but without the state file (a deleted run dir) their ports are taken, and by whom is said.
    const std::vector<HeldPort> held = heldPorts(set, {});
    const auto playbackPort = std::find_if(held.begin(), held.end(), [](const HeldPort& h) { return h.user == "LogPlayback"; });
    CPPUNIT_ASSERT(playbackPort != held.end());
    CPPUNIT_ASSERT_EQUAL(cluster.modulePort("LogPlayback"), playbackPort->port);
    CPPUNIT_ASSERT_EQUAL(static_cast<pid_t>(playback.pid), playbackPort->holder.pid);
    CPPUNIT_ASSERT(playbackPort->holder.command.find("rgnav-carmen-playback") != std::string::npos);

    stopLeftovers(set, leftovers);
    CPPUNIT_ASSERT(processGone(playback.pid, playbackStart));
    CPPUNIT_ASSERT(processGone(naming.pid, namingStart));
    CPPUNIT_ASSERT(leftoverModules(set).empty());
  }

  void testAnswerFromAnotherProcessGroupIsNotReady() {
    TestCluster cluster({impostorModule()}, kFastBackoff);
    PortHolderKiller impostor{cluster.modulePort("Impostor")};
    cluster.start({"NameService"});
    WatchdogClient& watchdog = cluster.watchdog();
    const SupervisionEvent hung = waitForEvent(watchdog, "Impostor", "hung");
    CPPUNIT_ASSERT_MESSAGE(hung.detail, hung.detail.find("no answer within the start timeout") != std::string::npos);
    CPPUNIT_ASSERT(eventsOf(watchdog, "Impostor", "ready").empty());
    // The impostor did answer on the module's port all along.
    const std::optional<PortHolder> holder = findPortHolder({"127.0.0.1", cluster.modulePort("Impostor")});
    CPPUNIT_ASSERT(holder && holder->command.find("rgnav-carmen-playback") != std::string::npos);
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(LeftoversIntegrationTest);
