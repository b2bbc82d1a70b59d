// rgnav-faulttest-navigation (`rgctl faulttest navigation`, issue "Exploration, tasks and the
// navigating demo"): the navigating demo (rgnav-demo on the modules of config/sets/demo.yaml, in
// a test cluster: own omniNames on free loopback ports, a temporary directory, the watchdog
// restarting every module without limit) runs twice: once undisturbed, once while every module of
// the set but the simulator is SIGKILLed `--kills` times in turn (FaultSchedule.h; omniNames once
// too), spread over 0.8 of the undisturbed run's duration. The disturbed demo must complete every
// task with no collision (its summary line: tasks=N/N collisions=0), every kill must be recovered,
// and its final map must hold as many regions and gateways as the undisturbed run's. Two runs of
// the real-time simulator differ in timing, so the maps are compared by their counts, not by their
// geometry (rgnav-faulttest-rgmap compares geometry on a replayed log, where timing does not
// matter). Lines: each run's summary, then
//   faulttest navigation: kills=… recovered=… tasks=…/… collisions=… regions=…/… gateways=…/…
//   time_s=…/… result=PASS|FAIL
// (undisturbed/disturbed where two numbers). Exit code 0 only on PASS. A run takes as long as the
// demo (tens of minutes on a loaded machine), so the suite does not run it.
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "core/config/ShippedConfig.h"
#include "tests/fault/FaultSchedule.h"
#include "tests/fault/MappingSet.h"
#include "tests/support/cluster/Interruption.h"
#include "tools/common/CommandLine.h"
#include "watchdog/Spawn.h"

namespace po = boost::program_options;
using namespace rgnav;
using namespace rgnav::testing;

namespace {

struct Options {
  int kills = 40;
  unsigned seed = 7;
  double limitSeconds = 5400.0;
};

// The demo's summary line as key=value pairs, and its exit status.
struct DemoResult {
  std::map<std::string, std::string> summary;
  int exitStatus = -1;
  double seconds = 0.0;

  std::string get(const std::string& key) const { return summary.count(key) ? summary.at(key) : "?"; }
};

std::map<std::string, std::string> summaryOf(const std::string& logFile) {
  std::ifstream in(logFile);
  std::string line, last;
  while (std::getline(in, line))
    if (line.rfind("demo: explored_share=", 0) == 0) last = line;
  std::map<std::string, std::string> fields;
  std::istringstream words(last.substr(std::min<std::size_t>(last.size(), 6)));
  for (std::string word; words >> word;)
    if (const auto eq = word.find('='); eq != std::string::npos) fields[word.substr(0, eq)] = word.substr(eq + 1);
  return fields;
}

// Starts rgnav-demo on the cluster; its output goes to `logFile`.
pid_t startDemo(TestCluster& cluster, const std::string& logFile) {
  SpawnSpec spec;
  spec.argv = {TestCluster::program("rgnav-demo"), "--world", shippedConfigFile("worlds/office.yaml"), "--answers",
               shippedConfigFile("demo/answers.yaml"), "--tasks", shippedConfigFile("demo/tasks.yaml"), "--out",
               cluster.dir(), "--name", "demo"};
  spec.env = {{"RGNAV_NAMING", "127.0.0.1:" + std::to_string(cluster.namingPort())}};
  spec.logFile = logFile;
  spec.parentDeathSignal = SIGKILL;
  return spawnProcess(spec);
}

DemoResult finishDemo(pid_t pid, const std::string& logFile, std::chrono::steady_clock::time_point begin,
                      double limitSeconds) {
  DemoResult result;
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() - begin > std::chrono::duration<double>(limitSeconds)) {
      discardChild(pid);
      throw std::runtime_error("the demo did not end within " + std::to_string(limitSeconds) + " s (" + logFile + ")");
    }
    sleepUntilOrInterrupted(std::chrono::steady_clock::now() + std::chrono::milliseconds(500));
  }
  result.exitStatus = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  result.summary = summaryOf(logFile);
  return result;
}

std::vector<std::string> faultTargets(const std::vector<ClusterModule>& modules) {
  std::vector<std::string> targets;
  for (const ClusterModule& m : modules)
    if (m.name != "Simulator") targets.push_back(m.name);
  return targets;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  po::options_description desc("rgnav-faulttest-navigation [options]");
  desc.add_options()
      ("help", "this text")
      ("kills", po::value(&options.kills)->default_value(options.kills),
       "SIGKILLs, dealt in turn to every module of the demo set but the simulator")
      ("seed", po::value(&options.seed)->default_value(options.seed), "seed for the fault schedule")
      ("limit-s", po::value(&options.limitSeconds)->default_value(options.limitSeconds), "a demo run longer than this fails");
  try {
    if (!parseCommandLine(argc, argv, desc)) return 0;
    catchInterruptions();  // a stopped run still shuts its server set down and removes its directory
    const std::string fastBackoff = "defaults: {backoff_initial_s: 0.05, backoff_max_s: 0.4}";
    const std::vector<ClusterModule> modules = shippedSetModules("sets/demo.yaml");

    DemoResult undisturbed;
    {
      TestCluster cluster(modules, fastBackoff);
      cluster.start();
      const std::string log = cluster.dir() + "/demo.log";
      const auto begin = std::chrono::steady_clock::now();
      undisturbed = finishDemo(startDemo(cluster, log), log, begin, options.limitSeconds);
      std::ifstream in(log);
      std::cout << "undisturbed run: exit " << undisturbed.exitStatus << ", " << in.rdbuf() << std::flush;
    }

    TestCluster cluster(modules, fastBackoff);
    cluster.start();
    const std::string log = cluster.dir() + "/demo.log";
    const auto begin = std::chrono::steady_clock::now();
    const pid_t demo = startDemo(cluster, log);
    const FaultRecord faults =
        injectFaults(cluster, {faultTargets(modules), options.kills, 0, 0.8 * undisturbed.seconds, options.seed});
    const DemoResult disturbed = finishDemo(demo, log, begin, options.limitSeconds);
    {
      std::ifstream in(log);
      std::cout << "run under faults: exit " << disturbed.exitStatus << ", " << in.rdbuf() << std::flush;
    }

    const std::string tasks = disturbed.get("tasks");
    const bool allTasks = tasks.find('/') != std::string::npos &&
                          tasks.substr(0, tasks.find('/')) == tasks.substr(tasks.find('/') + 1);
    const bool ok = disturbed.exitStatus == 0 && allTasks && disturbed.get("collisions") == "0" &&
                    faults.recovered == faults.kills && disturbed.get("regions") == undisturbed.get("regions") &&
                    disturbed.get("gateways") == undisturbed.get("gateways");
    std::printf("faulttest navigation: kills=%d recovered=%d naming_restarts=%d tasks=%s collisions=%s regions=%s/%s "
                "gateways=%s/%s time_s=%.0f/%.0f result=%s\n",
                faults.kills, faults.recovered, faults.namingRestarts, tasks.c_str(), disturbed.get("collisions").c_str(),
                undisturbed.get("regions").c_str(), disturbed.get("regions").c_str(), undisturbed.get("gateways").c_str(),
                disturbed.get("gateways").c_str(), undisturbed.seconds, disturbed.seconds, ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
  } catch (const po::error& e) {
    std::cerr << "rgnav-faulttest-navigation: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-faulttest-navigation: " << e.what() << std::endl;
  }
  return 2;
}
