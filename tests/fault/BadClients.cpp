// rgnav-faulttest-badclients (`rgctl faulttest badclients`): every server of the demo set survives
// every input a remote caller can give it. The mapping demo's set (config/sets/demo-mapping.yaml: the simulator's
// lock-step tour of the office floor -> ScanMapper -> GatewayDetection -> RG Mapping Kernel; with
// --log, a log playback instead of the simulator) maps twice: once undisturbed, once while
// `--threads` hostile clients (HostileClient.h) call every operation of every server, the watchdog
// included, with hostile arguments, and the watchdog restarts one module on request half way
// through (by the undisturbed run's duration; calls go on during the restart). Checks: no call ends in an unknown error (CORBA::UNKNOWN, an
// undeclared exception) or goes unanswered (a hung server), no server restarts other than the one
// asked for, no hostile export writes outside the export root or through a symbolic link, and the
// final map equals the undisturbed one. Last line:
//   badclients: calls=… typed_errors=… unknown_errors=0 server_restarts=0 map_identical=yes
//   unanswered=0 traps_intact=yes result=PASS
// Exit code 0 only if every check held and at least --min-calls calls were made.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <thread>

#include "tests/fault/FaultSchedule.h"
#include "tests/fault/HostileClient.h"
#include "tests/fault/MappingSet.h"
#include "tests/support/cluster/Interruption.h"
#include "tools/common/CommandLine.h"

namespace fs = std::filesystem;
namespace po = boost::program_options;
using namespace rgnav;
using namespace rgnav::testing;

namespace {

struct Options {
  std::string log;  // "" for the demo's simulator
  std::string models;
  std::string speed = "x60";
  unsigned threads = 4;
  std::uint64_t minCalls = 1000;
  int paceMs = 2;
  std::string restart = "GatewayDetection";
};

const char* const kUntouched = "not to be written by an export\n";
constexpr int kHangSeconds = 10;

// Symbolic links in the export root that point out of it, and the file they lead to.
struct Traps {
  ExportTraps names{"escape", "trap"};
  std::string outside;

  explicit Traps(const std::string& runDir) : outside(runDir + "/outside") {
    const std::string root = runDir + "/run/exports";
    fs::create_directories(root);
    fs::create_directories(outside);
    std::ofstream(outside + "/target") << kUntouched;
    fs::create_directory_symlink(outside, root + "/" + names.linkToOutside);
    fs::create_symlink(outside + "/target", root + "/" + names.linkFile + ".rgmap.json");
  }

  // Nothing was written beside the target, the target is unchanged and /etc got no export.
  bool intact() const {
    std::ifstream in(outside + "/target");
    const std::string content{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const auto entries = std::distance(fs::directory_iterator(outside), fs::directory_iterator());
    return content == kUntouched && entries == 1 && !fs::exists("/etc/badclients.rgmap.json");
  }
};

// The watchdog's restart count of every module of the set.
std::map<std::string, std::int64_t> restartCounts(TestCluster& cluster, const std::vector<ClusterModule>& modules) {
  std::map<std::string, std::int64_t> counts;
  for (const ClusterModule& m : modules) counts[m.name] = cluster.describe(m.name).restarts;
  return counts;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  po::options_description desc("rgnav-faulttest-badclients [options]");
  desc.add_options()
      ("help", "this text")
      ("log", po::value(&options.log)->default_value(options.log), "replay this log instead of the demo's simulator")
      ("models", po::value(&options.models), "trained gateway HMMs for the log's set (config/gateways/gateway-hmms.txt)")
      ("speed", po::value(&options.speed)->default_value(options.speed), "replay speed of the log (x<k> or realtime)")
      ("threads", po::value(&options.threads)->default_value(options.threads), "hostile clients calling at once")
      ("min-calls", po::value(&options.minCalls)->default_value(options.minCalls),
       "hostile calls at least (they go on after the end of the map until there are this many)")
      ("pace-ms", po::value(&options.paceMs)->default_value(options.paceMs), "pause of each client between two calls")
      ("restart", po::value(&options.restart)->default_value(options.restart),
       "module the watchdog restarts half way through the map (\"\" for none)");
  try {
    if (!parseCommandLine(argc, argv, desc)) return 0;
    if (options.threads == 0) throw po::error("--threads must be at least 1");
    if (!options.log.empty() && options.models.empty()) throw po::error("--log needs --models");
    catchInterruptions();  // a stopped run still shuts its server sets down and removes their directories
    const bool simulator = options.log.empty();
    const auto modules = simulator ? demoSet() : mappingSet(options.log, options.models, options.speed);
    const double limitSeconds = simulator ? 900 : replayDuration(options.log, options.speed) + 300;

    nlohmann::json reference;
    double undisturbedSeconds = 0.0;
    {
      TestCluster cluster(modules);
      cluster.start();
      const auto start = std::chrono::steady_clock::now();
      waitForEndOfMap(cluster, limitSeconds);
      undisturbedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      reference = finishedMap(cluster, limitSeconds);
    }
    std::cout << "undisturbed map: " << reference["summary"].dump() << " in " << undisturbedSeconds << " s" << std::endl;

    TestCluster cluster(modules);
    cluster.start();
    const Traps traps(cluster.dir());
    const auto restartsBefore = restartCounts(cluster, modules);

    HostileTally tally;
    std::atomic<bool> stop{false};
    // A call unanswered after kHangSeconds counts as a hung server. Not the tools' 2 s: a whole-map
    // export (one of the hostile calls succeeds as one) takes seconds on a loaded machine, and the
    // calls queued behind it wait as long.
    ClientSettings hostile = cluster.clientSettings();
    hostile.callTimeout = std::chrono::seconds(kHangSeconds);
    std::vector<std::thread> clients;
    for (unsigned i = 0; i < options.threads; ++i)
      clients.emplace_back([&, i] {
        HostileClient client(hostile, HostPort{"127.0.0.1", cluster.watchdogPort()}, traps.names, simulator,
                             simulator, i);
        while (!stop) {
          client.callNext(tally);
          std::this_thread::sleep_for(std::chrono::milliseconds(options.paceMs));
        }
      });
    const auto stopClients = [&] {
      stop = true;
      for (std::thread& t : clients) t.join();
      clients.clear();
    };

    std::uint64_t whileMapping = 0;  // calls made before the kernel had the whole tour or log
    std::int64_t asked = 0;  // what the restart the run asked for added to the module's count
    try {
      if (!options.restart.empty()) {
        sleepUntilOrInterrupted(std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                                     std::chrono::duration<double>(0.5 * undisturbedSeconds)));
        const auto old = cluster.describe(options.restart);
        cluster.watchdog().restartModule(options.restart);
        const auto again =
            cluster.waitFor(options.restart, [&](const ModuleProcessInfo& m) { return isRunning(m) && m.pid != old.pid; },
                            "running again after the restart", std::chrono::seconds(60));
        asked = std::int64_t(again.restarts) - std::int64_t(old.restarts);
      }
      waitForEndOfMap(cluster, limitSeconds);
      whileMapping = tally.calls;
      while (tally.calls < options.minCalls)
        sleepUntilOrInterrupted(std::chrono::steady_clock::now() + std::chrono::milliseconds(100));
    } catch (...) {
      stopClients();
      throw;
    }
    stopClients();

    const auto restartsAfter = restartCounts(cluster, modules);
    std::int64_t unexpectedRestarts = 0;
    for (const auto& [name, before] : restartsBefore)
      unexpectedRestarts += restartsAfter.at(name) - before - (name == options.restart ? asked : 0);
    const nlohmann::json disturbed = finishedMap(cluster, 60);
    std::cout << "map under hostile calls: " << disturbed["summary"].dump() << std::endl;
    for (const std::string& note : tally.notes()) std::cout << "call: " << note << "\n";
    std::printf("badclients_by_kind: while_mapping=%llu accepted=%llu invalid_argument=%llu not_available=%llu "
                "not_supported=%llu failed=%llu\n",
                static_cast<unsigned long long>(whileMapping), static_cast<unsigned long long>(tally.accepted.load()),
                static_cast<unsigned long long>(tally.invalidArgument.load()),
                static_cast<unsigned long long>(tally.notAvailable.load()),
                static_cast<unsigned long long>(tally.notSupported.load()),
                static_cast<unsigned long long>(tally.failed.load()));

    const bool identical = disturbed == reference;
    const bool intact = traps.intact();
    const bool ok = tally.unknown == 0 && tally.unanswered == 0 && unexpectedRestarts == 0 && identical && intact &&
                    tally.calls >= options.minCalls;
    std::printf("badclients: calls=%llu typed_errors=%llu unknown_errors=%llu server_restarts=%lld map_identical=%s "
                "unanswered=%llu traps_intact=%s result=%s\n",
                static_cast<unsigned long long>(tally.calls.load()), static_cast<unsigned long long>(tally.typed()),
                static_cast<unsigned long long>(tally.unknown.load()), static_cast<long long>(unexpectedRestarts),
                identical ? "yes" : "no", static_cast<unsigned long long>(tally.unanswered.load()), intact ? "yes" : "no",
                ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
  } catch (const po::error& e) {
    std::cerr << "rgnav-faulttest-badclients: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-faulttest-badclients: " << e.what() << std::endl;
  }
  return 2;
}
