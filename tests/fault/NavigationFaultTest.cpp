// rgnav-faulttest-navigation: fault injection on the navigating demo (issue "Exploration, tasks and
// the navigating demo", `rgctl faulttest navigation`). The demo's whole robot (config/sets/demo.yaml,
// in a test cluster: free loopback ports, a temporary directory, its own omniNames; the kernel
// exports there) runs the demo (rgnav-demo: explore the office, name three regions, three tasks)
// twice: once undisturbed (or its facts are read from --reference), once while every module of
// the set but the simulator is SIGKILLed in turn (40 kills by default, by the PID the watchdog
// reports, spread evenly over 85 % of the undisturbed run's time, each after the previous victim
// runs again under a new PID). Each run's lines are echoed ("undisturbed | …", "faults | …").
// The disturbed demo must explore, reach every task and collide with nothing (its exit code and
// summary line), the watchdog must have restarted each victim and nothing else, and the final map
// must have the same number of regions and gateways and the same region names as the undisturbed
// one; the gateways' classes, the neutralised gateways and the regions' total area are compared
// and reported, not required (the robot drives another path under faults, and a gateway's class
// is the detector's belief from the scans it saw). Last line:
//   faulttest navigation: kills=40 restarts=40 tasks=3/3 collisions=0 regions=…/… gateways=…/…
//   neutralized=…/… names=same classes=same|differ area_m2=…/… result=PASS
// (disturbed/undisturbed). Exit code 0 only if every required check held.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <thread>

#include "core/config/ShippedConfig.h"
#include "tests/fault/DemoRun.h"
#include "tests/fault/FaultSchedule.h"
#include "tests/fault/MappingSet.h"
#include "tests/support/cluster/Interruption.h"
#include "tools/common/CommandLine.h"

namespace po = boost::program_options;
using namespace rgnav;
using namespace rgnav::testing;
using nlohmann::json;

namespace {

struct Options {
  int kills = 40;
  unsigned seed = 7;
  DemoFiles files{shippedConfigFile("worlds/office.yaml"), shippedConfigFile("demo/answers.yaml"),
                  shippedConfigFile("demo/tasks.yaml")};
  std::string start;  // the simulator's --start; empty: the set's
  std::string reference, saveReference;
  double spanS = 0.0;  // 0: 85 % of the undisturbed run's time
  int limitS = 5400;
};

// An undisturbed run's result: its summary line and its map's facts.
struct Reference {
  std::map<std::string, std::string> summary;
  MapFacts facts;
};

std::vector<ClusterModule> demoRobot(const Options& options) {
  std::vector<ClusterModule> modules = shippedSetModules("sets/demo.yaml");
  for (ClusterModule& m : modules) {
    if (m.name != "Simulator") continue;
    for (std::size_t i = 0; i + 1 < m.command.size(); ++i) {
      if (m.command[i] == "--world") m.command[i + 1] = options.files.world;
      if (m.command[i] == "--start" && !options.start.empty()) m.command[i + 1] = options.start;
    }
  }
  return modules;
}

// Every module of the set but the simulator.
std::vector<std::string> victims(const std::vector<ClusterModule>& modules) {
  std::vector<std::string> names;
  for (const ClusterModule& m : modules)
    if (m.name != "Simulator") names.push_back(m.name);
  return names;
}

std::map<std::string, std::uint32_t> restartCounts(TestCluster& cluster, const std::vector<ClusterModule>& modules) {
  std::map<std::string, std::uint32_t> counts;
  for (const ClusterModule& m : modules) counts[m.name] = cluster.describe(m.name).restarts;
  return counts;
}

// Whether the summary's "tasks=N/M" says every task was reached.
bool allReached(const std::string& tasks) {
  const auto slash = tasks.find('/');
  return slash != std::string::npos && slash > 0 && tasks.substr(0, slash) == tasks.substr(slash + 1);
}

const std::string kFaultSettings = "defaults: {backoff_initial_s: 0.05, backoff_max_s: 0.4}";

Reference undisturbedRun(const Options& options) {
  if (!options.reference.empty()) {
    std::ifstream in(options.reference);
    if (!in) throw FileError("cannot read the reference " + options.reference);
    const json saved = json::parse(in);
    return {saved.at("summary").get<std::map<std::string, std::string>>(), mapFactsFromJson(saved.at("map"))};
  }
  TestCluster cluster(demoRobot(options), kFaultSettings);
  cluster.start();
  const DemoOutcome demo =
      runDemo(cluster, options.files, "undisturbed", "undisturbed | ", std::chrono::seconds(options.limitS));
  Reference reference{demo.summary, mapFacts(exportedMap(cluster, "undisturbed"))};
  if (demo.exitCode != 0) std::cout << "undisturbed: the demo ended with exit code " << demo.exitCode << std::endl;
  if (!options.saveReference.empty())
    std::ofstream(options.saveReference) << json{{"summary", reference.summary}, {"map", toJson(reference.facts)}}.dump(2)
                                         << "\n";
  return reference;
}

// The seconds the kills are spread over: --span-s, or 85 % of the undisturbed run's time.
double killSpan(const Options& options, const Reference& reference) {
  if (options.spanS > 0) return options.spanS;
  const auto time = reference.summary.find("time_s");
  if (time == reference.summary.end())
    throw NotAvailableError("the undisturbed demo printed no time_s; give --span-s");
  return 0.85 * std::stod(time->second);
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : ",") + w;
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  po::options_description desc("rgnav-faulttest-navigation [options]");
  desc.add_options()
      ("help", "this text")
      ("kills", po::value(&options.kills)->default_value(options.kills),
       "SIGKILLs, dealt in turn to every module of the set but the simulator")
      ("seed", po::value(&options.seed)->default_value(options.seed), "seed of the fault schedule")
      ("world", po::value(&options.files.world)->default_value(options.files.world), "the simulator's world")
      ("start", po::value(&options.start), "the robot's start x,y,theta in the world (default: the set's)")
      ("answers", po::value(&options.files.answers)->default_value(options.files.answers), "the demo user's names")
      ("tasks", po::value(&options.files.tasks)->default_value(options.files.tasks), "the demo's tasks")
      ("reference", po::value(&options.reference),
       "the undisturbed run's facts (written by --save-reference) instead of running it")
      ("save-reference", po::value(&options.saveReference), "write the undisturbed run's facts to this file")
      ("span-s", po::value(&options.spanS)->default_value(options.spanS),
       "seconds the kills are spread over (0: 85 % of the undisturbed run's time_s)")
      ("limit-s", po::value(&options.limitS)->default_value(options.limitS), "each demo run is stopped after this");
  try {
    if (!parseCommandLine(argc, argv, desc)) return 0;
    catchInterruptions();  // a stopped run still shuts its server set down and removes its directory
    const Reference reference = undisturbedRun(options);
    const double span = killSpan(options, reference);
    std::printf("undisturbed: tasks=%s collisions=%s regions=%zu gateways=%zu names=%s; %d kills over %.0f s\n",
                reference.summary.count("tasks") ? reference.summary.at("tasks").c_str() : "?",
                reference.summary.count("collisions") ? reference.summary.at("collisions").c_str() : "?",
                reference.facts.regions, reference.facts.gateways, joined(reference.facts.regionNames).c_str(),
                options.kills, span);
    std::fflush(stdout);

    const std::vector<ClusterModule> modules = demoRobot(options);
    TestCluster cluster(modules, kFaultSettings);
    cluster.start();
    const std::map<std::string, std::uint32_t> before = restartCounts(cluster, modules);
    std::atomic<bool> demoOver{false};
    FaultRecord faults;
    std::exception_ptr faultError;
    std::thread injector([&] {
      try {
        faults = injectFaults(cluster, {victims(modules), options.kills, 0, span, options.seed, false,
                                        [&] { return demoOver.load(); }});
      } catch (...) {
        faultError = std::current_exception();
      }
    });
    DemoOutcome demo;
    try {
      demo = runDemo(cluster, options.files, "faults", "faults | ", std::chrono::seconds(options.limitS));
    } catch (...) {
      demoOver = true;
      injector.join();
      throw;
    }
    demoOver = true;
    injector.join();
    if (faultError) std::rethrow_exception(faultError);
    const std::map<std::string, std::uint32_t> after = restartCounts(cluster, modules);
    const MapFacts facts = mapFacts(exportedMap(cluster, "faults"));

    int restarts = 0;
    std::string perModule;
    for (const auto& [name, count] : after) {
      restarts += static_cast<int>(count - before.at(name));
      perModule += " " + name + "=" + std::to_string(count - before.at(name));
    }
    std::printf("restarts:%s\n", perModule.c_str());
    if (!faults.recoverySeconds.empty())
      std::printf("recovery: longest %.2f s\n",
                  *std::max_element(faults.recoverySeconds.begin(), faults.recoverySeconds.end()));
    const bool sameNames = facts.regionNames == reference.facts.regionNames;
    const bool ok = faults.kills == options.kills && restarts == faults.kills && demo.exitCode == 0 &&
                    allReached(demo.field("tasks")) && demo.field("collisions") == "0" &&
                    facts.regions == reference.facts.regions && facts.gateways == reference.facts.gateways && sameNames;
    if (!sameNames)
      std::printf("region names: %s vs %s\n", joined(facts.regionNames).c_str(), joined(reference.facts.regionNames).c_str());
    std::printf("faulttest navigation: kills=%d restarts=%d tasks=%s collisions=%s regions=%zu/%zu gateways=%zu/%zu "
                "neutralized=%zu/%zu names=%s classes=%s area_m2=%.0f/%.0f exit=%d result=%s\n",
                faults.kills, restarts, demo.field("tasks").c_str(), demo.field("collisions").c_str(), facts.regions,
                reference.facts.regions, facts.gateways, reference.facts.gateways, facts.neutralised, reference.facts.neutralised,
                sameNames ? "same" : "differ", facts.gatewayClasses == reference.facts.gatewayClasses ? "same" : "differ",
                facts.areaM2, reference.facts.areaM2, demo.exitCode, ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
  } catch (const po::error& e) {
    std::cerr << "rgnav-faulttest-navigation: " << e.what() << "\n" << desc << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-faulttest-navigation: " << e.what() << std::endl;
  }
  return 2;
}
