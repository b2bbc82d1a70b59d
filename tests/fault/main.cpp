// rgnav-faulttest: fault injection on a full log replay through the real server set (omniNames
// + watchdog + log playback [+ ScanMapper] + rgnav-cat as consumer). While the log plays, the
// target module (the playback server, or with --target ScanMapper the scan mapper) is SIGKILLed
// and SIGSTOPped many times and omniNames is killed once; a second module that crashes at every
// start must end FATAL while the others keep running. The consumer must receive every scan
// (raw, or corrected) exactly once and in order; with the ScanMapper, every scan's final
// corrected pose must equal the fault-free run's (the SLAM core in-process) within 1 mm. Last line:
//   faults: kills=50 stops=5 recovered=55 scans_expected=910 scans_received=910 duplicates=0 ...
// Exit code 0 only if every check held.
#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "clientlibs/scanmapper/ScanMapperClient.h"
#include "core/logs/OpenLog.h"
#include "core/slam/ScanMapper.h"
#include "tests/fault/FaultSchedule.h"
#include "tests/support/cluster/Interruption.h"
#include "tests/support/cluster/TestCluster.h"
#include "watchdog/Spawn.h"
#include "tools/common/CommandLine.h"
#include "tests/support/Statistics.h"

namespace po = boost::program_options;
using namespace rgnav;
using namespace rgnav::testing;
using Clock = std::chrono::steady_clock;

namespace {

struct Options {
  std::string target = "LogPlayback";
  int kills = 50;
  int stops = 5;
  std::string log;
  std::string corrected;
  std::string speed = "x60";
  unsigned seed = 7;
  double toleranceMm = 1.0;
};

std::size_t scansInLog(const std::string& path) {
  auto source = openLog(path);
  std::size_t scans = 0;
  while (auto record = source->next()) scans += std::holds_alternative<LaserScan>(*record);
  return scans;
}

// IDs the consumer recorded, in arrival order.
std::vector<DataId> recordedIds(const std::string& file) {
  std::vector<DataId> ids;
  std::ifstream in(file);
  std::string kind;
  DataId id;
  std::string rest;
  while (in >> kind >> id && std::getline(in, rest)) ids.push_back(id);
  return ids;
}

// The fault-free reference: the SLAM core in-process on the same log, as the module runs it.
std::vector<Pose2D> referencePoses(const std::string& log, const std::string& corrected) {
  LogReaderOptions reader;
  reader.correctedPosesPath = corrected;
  auto source = openLog(log, reader);
  ScanMapper mapper;
  while (auto record = source->next())
    if (const auto* scan = std::get_if<LaserScan>(&*record)) mapper.addScan(*scan);
  mapper.optimize();
  std::vector<Pose2D> poses;
  for (DataId id = 1; id <= mapper.lastInputId(); ++id) poses.push_back(mapper.correctedPose(id));
  return poses;
}

// Largest distance (mm) between the module's final poses and the reference; +inf if any is missing.
double largestPoseDifferenceMm(ScanMapperClient& mapper, const std::vector<Pose2D>& reference) {
  double largest = 0.0;
  for (DataId first = 1; first <= reference.size();) {
    const auto updates = mapper.poses(first, reference.size());
    if (updates.empty()) return std::numeric_limits<double>::infinity();
    for (const PoseUpdate& u : updates) {
      const Pose2D& r = reference[u.id - 1];
      largest = std::max(largest, 1000.0 * std::hypot(u.corrected.x - r.x, u.corrected.y - r.y));
    }
    first = updates.back().id + 1;
  }
  return largest;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  options.log = TestCluster::shared("data/laser/corrected/intel-corrected.log.gz");
  po::options_description desc("rgnav-faulttest [options]");
  desc.add_options()
      ("help", "this text")
      ("target", po::value(&options.target)->default_value(options.target), "module to hurt: LogPlayback or ScanMapper")
      ("kills", po::value(&options.kills)->default_value(options.kills), "SIGKILLs of the target")
      ("stops", po::value(&options.stops)->default_value(options.stops), "SIGSTOPs of the target")
      ("log", po::value(&options.log)->default_value(options.log), "log to replay")
      ("corrected", po::value(&options.corrected)->default_value(""), "Intel JSON only: the corrected-pose companion")
      ("tolerance-mm", po::value(&options.toleranceMm)->default_value(options.toleranceMm),
       "ScanMapper: largest allowed pose difference to the fault-free run")
      ("speed", po::value(&options.speed)->default_value(options.speed), "replay speed (x<k> or realtime)")
      ("seed", po::value(&options.seed)->default_value(options.seed), "seed for the fault schedule");
  try {
    if (!rgnav::parseCommandLine(argc, argv, desc)) return 0;
    catchInterruptions();  // a stopped run still shuts its server set down and removes its directory

    const bool mapping = options.target == "ScanMapper";
    if (!mapping && options.target != "LogPlayback") throw InvalidArgumentError("--target is LogPlayback or ScanMapper");
    const std::size_t expected = scansInLog(options.log);
    const double replaySeconds = replayDuration(options.log, options.speed);
    std::vector<std::string> playback{TestCluster::program("rgnav-carmen-playback"), "--log", options.log, "--speed",
                                      options.speed};
    if (!options.corrected.empty()) playback.insert(playback.end(), {"--corrected", options.corrected});
    std::vector<ClusterModule> modules{
        {"LogPlayback", playback, {"Laser", "Base"}, {}, "max_restarts: 1000"},
        {"CrashAtStart", {TestCluster::program("rgnav-carmen-playback"), "--log", "/nonexistent/crash-at-start.log"},
         {"CrashLaser"}, {}, "max_restarts: 3"}};
    if (mapping)
      modules.push_back({"ScanMapper",
                         {TestCluster::program("rgnav-scanmapper"), "--config", TestCluster::moduleConfig("scanmapper")},
                         {"ScanMapper"},
                         {"LogPlayback"},
                         "max_restarts: 1000"});
    TestCluster cluster(modules, "defaults: {backoff_initial_s: 0.05, backoff_max_s: 0.4}");
    cluster.start({"LogPlayback", options.target});

    SpawnSpec consumer;
    consumer.argv = {TestCluster::program("rgnav-cat"), mapping ? "corrected" : "laser", "--quiet", "--record",
                     cluster.dir() + "/received.txt",
                     "--naming", "127.0.0.1:" + std::to_string(cluster.namingPort()), "--retry-budget-ms", "30000"};
    consumer.logFile = cluster.dir() + "/consumer.log";
    consumer.parentDeathSignal = SIGTERM;
    const pid_t consumerPid = spawnProcess(consumer);

    // Faults spread over 85 % of the replay, in a seeded order; omniNames dies half way.
    const FaultRecord faults =
        injectFaults(cluster, {{options.target}, options.kills, options.stops, 0.85 * replaySeconds, options.seed});

    int status = 0;
    const auto giveUp = Clock::now() + std::chrono::duration<double>(replaySeconds + 120);
    while (::waitpid(consumerPid, &status, WNOHANG) == 0) {
      if (Clock::now() > giveUp) {
        ::kill(consumerPid, SIGKILL);
        ::waitpid(consumerPid, &status, 0);
        std::cerr << "consumer did not finish" << std::endl;
        break;
      }
      sleepUntilOrInterrupted(Clock::now() + std::chrono::milliseconds(50));
    }

    const std::vector<DataId> ids = recordedIds(cluster.dir() + "/received.txt");
    std::size_t duplicates = 0, outOfOrder = 0;
    std::vector<int> seen(expected + 2, 0);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (ids[i] < seen.size() && seen[ids[i]]++) ++duplicates;
      if (i > 0 && ids[i] <= ids[i - 1]) ++outOfOrder;
    }
    const std::size_t distinct = std::count_if(seen.begin(), seen.end(), [](int n) { return n > 0; });
    const auto crash = cluster.describe("CrashAtStart");
    const auto target = cluster.describe(options.target);
    const auto naming = cluster.describe("NameService");
    const bool othersRun = isRunning(cluster.describe("LogPlayback")) && isRunning(target) && isRunning(naming);
    const bool everyFaultRestarted = target.restarts == static_cast<std::uint32_t>(faults.kills + faults.stops);
    double poseDifferenceMm = 0.0;
    if (mapping) {
      ScanMapperClient mapper(cluster.clientSettings());
      poseDifferenceMm = largestPoseDifferenceMm(mapper, referencePoses(options.log, options.corrected));
    }

    std::cout << "consumer: " << [&] {
      std::ifstream in(cluster.dir() + "/consumer.log");
      std::string line, last;
      while (std::getline(in, line)) last = line;
      return last;
    }() << "\n";
    std::cout << "CrashAtStart: " << toString(crash.state) << " after " << crash.restarts
              << " restarts (" << crash.lastEvent << ")\n";
    std::cout << options.target << ": " << toString(target.state) << ", restarts=" << target.restarts
              << "; NameService: " << toString(naming.state) << ", restarts=" << naming.restarts << "\n";
    if (mapping) std::printf("largest pose difference to the fault-free run: %.4f mm\n", poseDifferenceMm);
    const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 && ids.size() == expected && distinct == expected &&
                    duplicates == 0 && outOfOrder == 0 && faults.recovered == faults.kills + faults.stops &&
                    crash.state == ProcessState::Fatal && othersRun && everyFaultRestarted && faults.namingRestarts == 1 &&
                    poseDifferenceMm <= options.toleranceMm;
    std::printf("faults: target=%s kills=%d stops=%d recovered=%d scans_expected=%zu scans_received=%zu "
                "duplicates=%zu out_of_order=%zu naming_restarts=%d crash_at_start=%s recovery_p95_s=%.3f",
                options.target.c_str(), faults.kills, faults.stops, faults.recovered, expected, ids.size(), duplicates,
                outOfOrder, faults.namingRestarts, toString(crash.state), percentile(faults.recoverySeconds, 0.95));
    if (mapping) std::printf(" max_pose_diff_mm=%.4f", poseDifferenceMm);
    std::printf(" result=%s\n", ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
  } catch (const po::error& e) {
    std::cerr << "rgnav-faulttest: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-faulttest: " << e.what() << std::endl;
  }
  return 2;
}
