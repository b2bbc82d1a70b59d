// integration_module_config_test: the ScanMapper, GatewayDetection and RG Mapping Kernel servers
// take their parameters only from --config (config/modules/<module>.yaml): without the option, with
// a file that does not exist and with a file holding an unknown key, each stops at start with
// exit status 2 and a message naming the option, the file or the key path.
#include <cppunit/extensions/HelperMacros.h>
#include <sys/wait.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/config/DescribedConfig.h"
#include "tests/integration/IntegrationHelpers.h"
#include "watchdog/Spawn.h"

using namespace rgnav;
using namespace rgnav::testing;

namespace {

struct Server {
  std::string program;
  std::string module;
};

const std::vector<Server> kServers{{"rgnav-scanmapper", "scanmapper"},
                                   {"rgnav-gatewaydetection", "gatewaydetection"},
                                   {"rgnav-rgmappingkernel", "rgmappingkernel"}};

// Runs the server with `configArgs` until it ends; returns its exit status and output. It
// listens on a free port and is pointed at a naming port where nothing listens: it must stop
// before it needs either.
std::pair<int, std::string> runUntilExit(const Server& server, const std::vector<std::string>& configArgs,
                                         const ScratchDir& scratch) {
  SpawnSpec spec;
  spec.argv = {TestCluster::program(server.program), "--module", "M", "--endpoint",
               "127.0.0.1:" + std::to_string(freeLoopbackPort()), "--naming",
               "127.0.0.1:" + std::to_string(freeLoopbackPort())};
  spec.argv.insert(spec.argv.end(), configArgs.begin(), configArgs.end());
  spec.logFile = scratch.file(server.module + ".log");
  std::filesystem::remove(spec.logFile);
  spec.parentDeathSignal = SIGKILL;
  const pid_t pid = spawnProcess(spec);
  int status = 0;
  try {
    waitUntil([&] { return ::waitpid(pid, &status, WNOHANG) != 0; }, server.program + " to stop",
              std::chrono::seconds(30), std::chrono::milliseconds(20));
  } catch (...) {
    discardChild(pid);
    throw;
  }
  CPPUNIT_ASSERT_MESSAGE(server.program + " ended by a signal", WIFEXITED(status));
  std::ifstream log(spec.logFile);
  return {WEXITSTATUS(status), std::string(std::istreambuf_iterator<char>(log), std::istreambuf_iterator<char>())};
}

void expectStartError(const Server& server, const std::vector<std::string>& configArgs, const std::string& expected,
                      const ScratchDir& scratch) {
  const auto [status, output] = runUntilExit(server, configArgs, scratch);
  CPPUNIT_ASSERT_EQUAL_MESSAGE(output, 2, status);
  CPPUNIT_ASSERT_MESSAGE(server.program + " said: " + output, output.find(expected) != std::string::npos);
}

}  // namespace

class ModuleConfigIntegrationTest : public CppUnit::TestFixture {
  CPPUNIT_TEST_SUITE(ModuleConfigIntegrationTest);
  CPPUNIT_TEST(stopsWithoutConfig);
  CPPUNIT_TEST(stopsForMissingFile);
  CPPUNIT_TEST(stopsForUnknownKey);
  CPPUNIT_TEST_SUITE_END();

 public:
  void stopsWithoutConfig() {
    const ScratchDir scratch("rgnav-module-config");
    for (const Server& server : kServers) expectStartError(server, {}, "--config", scratch);
  }

  void stopsForMissingFile() {
    const ScratchDir scratch("rgnav-module-config");
    const std::string missing = scratch.file("missing.yaml");
    for (const Server& server : kServers)
      expectStartError(server, {"--config", missing}, missing + ": cannot read", scratch);
  }

  void stopsForUnknownKey() {
    const ScratchDir scratch("rgnav-module-config");
    for (const Server& server : kServers) {
      const std::string file = scratch.file(server.module + ".yaml");
      std::ofstream(file) << readConfigFile(TestCluster::moduleConfig(server.module)) << "max_speed_mps: 1\n";
      expectStartError(server, {"--config", file}, file + ": max_speed_mps: unknown key", scratch);
    }
  }
};

CPPUNIT_TEST_SUITE_REGISTRATION(ModuleConfigIntegrationTest);
