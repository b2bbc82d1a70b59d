// integration_interrupted_run_test: a long evaluation that runs a server set (the RG Map fault
// test, rgnav-faulttest-rgmap) stopped with Ctrl-C (SIGINT) while its set runs. It must end
// with exit status 2, remove its cluster directory and leave no process whose command line names
// that directory (Interruption.h). The program's temporary directory is this test's own (TMPDIR).
#include <cppunit/extensions/HelperMacros.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <thread>

#include "tests/integration/IntegrationHelpers.h"
#include "watchdog/Spawn.h"

using namespace rgnav;
using namespace rgnav::testing;
namespace fs = std::filesystem;

namespace {

// Kills the program by PID if the test ends before it did.
struct Child {
  pid_t pid = -1;
  ~Child() {
    if (pid > 0) discardChild(pid);
  }
};

std::optional<fs::path> clusterDirIn(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().rfind("rgnav-cluster-", 0) == 0) return entry.path();
  return std::nullopt;
}

// PIDs of the processes whose command line contains `text`.
std::vector<pid_t> processesNaming(const std::string& text) {
  std::vector<pid_t> found;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(entry.path() / "cmdline", std::ios::binary);
    const std::string cmdline{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (cmdline.find(text) != std::string::npos) found.push_back(std::stoi(name));
  }
  return found;
}

}  // namespace

class InterruptedRunIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(InterruptedRunIntegrationTest);
  CPPUNIT_TEST(stoppedEvaluationRemovesItsServerSet);
  CPPUNIT_TEST_SUITE_END();

 public:
  void stoppedEvaluationRemovesItsServerSet() {
    const ScratchDir scratch("rgnav-interrupted");  // the program's TMPDIR
    SpawnSpec spec;
    spec.argv = {TestCluster::program("rgnav-faulttest-rgmap"), "--models",
                 std::string(std::getenv("RGNAV_ROOT")) + "/config/gateways/gateway-hmms.txt"};
    spec.env = {{"TMPDIR", scratch.path.string()}};
    spec.logFile = scratch.file("faulttest.log");
    spec.parentDeathSignal = SIGKILL;
    Child child{spawnProcess(spec)};

    // Wait for the set to run: its ScanMapper module names the cluster directory.
    std::optional<fs::path> cluster;
    waitUntil(
        [&] {
          CPPUNIT_ASSERT_EQUAL_MESSAGE("the program ended early", 0, ::waitpid(child.pid, nullptr, WNOHANG));
          cluster = clusterDirIn(scratch.path);
          return cluster && processesNaming(cluster->string() + "/").size() >= 2;
        },
        "the server set to start", std::chrono::seconds(120), std::chrono::milliseconds(50));
    // A second of mapping is the scenario: the Ctrl-C lands in a running chain, not in its start.
    std::this_thread::sleep_for(std::chrono::seconds(1));

    CPPUNIT_ASSERT_EQUAL(0, ::kill(child.pid, SIGINT));
    int status = 0;
    waitUntil([&] { return ::waitpid(child.pid, &status, WNOHANG) != 0; }, "the program to end after SIGINT",
              std::chrono::seconds(60), std::chrono::milliseconds(50));
    child.pid = -1;
    CPPUNIT_ASSERT_MESSAGE("ended by a signal, not by unwinding", WIFEXITED(status));
    CPPUNIT_ASSERT_EQUAL(2, WEXITSTATUS(status));
    CPPUNIT_ASSERT_MESSAGE("the cluster directory is left", !fs::exists(*cluster));
    // The set's processes got SIGKILL at the latest; give the kernel time to remove them.
    waitUntil([&] { return processesNaming(cluster->string() + "/").empty(); }, "every process of the set to end",
              std::chrono::seconds(10), std::chrono::milliseconds(50));
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(InterruptedRunIntegrationTest);
