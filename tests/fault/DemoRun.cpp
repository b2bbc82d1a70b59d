// The navigating demo run as a child process, and the facts of its map (see DemoRun.h).
#include "tests/fault/DemoRun.h"

#include <sys/wait.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "tests/support/cluster/Interruption.h"
#include "watchdog/Spawn.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace rgnav::testing {
namespace {

constexpr const char* kSummaryStart = "demo: explored_share=";

// Echoes the lines of a growing file as they are completed.
class LineFollower {
 public:
  LineFollower(std::string file, std::string prefix) : file_(std::move(file)), prefix_(std::move(prefix)) {}

  // Prints the lines completed since the last call; remembers the latest summary line.
  void poll() {
    std::ifstream in(file_);
    in.seekg(static_cast<std::streamoff>(offset_));
    for (std::string line; std::getline(in, line) && !in.eof();) {
      offset_ += line.size() + 1;
      std::cout << prefix_ << line << "\n";
      if (line.rfind(kSummaryStart, 0) == 0) summary_ = line;
    }
    std::cout.flush();
  }

  const std::string& summary() const { return summary_; }

 private:
  std::string file_, prefix_, summary_;
  std::size_t offset_ = 0;
};

std::map<std::string, std::string> parseSummary(const std::string& line) {
  std::map<std::string, std::string> fields;
  std::istringstream words(line.substr(std::string("demo: ").size()));
  for (std::string word; words >> word;)
    if (const auto eq = word.find('='); eq != std::string::npos) fields[word.substr(0, eq)] = word.substr(eq + 1);
  return fields;
}

std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

std::string DemoOutcome::field(const std::string& key, const std::string& fallback) const {
  const auto it = summary.find(key);
  return it == summary.end() ? fallback : it->second;
}

DemoOutcome runDemo(TestCluster& cluster, const DemoFiles& files, const std::string& name, const std::string& prefix,
                    std::chrono::seconds limit) {
  const std::string out = cluster.dir() + "/" + name;
  fs::create_directories(out);
  const ClientSettings settings = cluster.clientSettings();
  SpawnSpec spec;
  spec.argv = {TestCluster::program("rgnav-demo"), "--world", files.world, "--answers", files.answers, "--tasks",
               files.tasks, "--out", out, "--name", name};
  spec.env = {{"RGNAV_NAMING", settings.namingHost + ":" + std::to_string(settings.namingPort)},
              {"RGNAV_ROBOT", settings.robot}};
  spec.logFile = out + "/demo.log";
  spec.parentDeathSignal = SIGKILL;
  const pid_t pid = spawnProcess(spec);
  LineFollower lines(spec.logFile, prefix);
  const auto giveUp = std::chrono::steady_clock::now() + limit;
  int status = 0;
  try {
    while (::waitpid(pid, &status, WNOHANG) == 0) {
      lines.poll();
      if (std::chrono::steady_clock::now() > giveUp)
        throw std::runtime_error("rgnav-demo did not end within " + std::to_string(limit.count()) + " s");
      sleepUntilOrInterrupted(std::chrono::steady_clock::now() + std::chrono::milliseconds(200));
    }
  } catch (...) {
    discardChild(pid);
    throw;
  }
  lines.poll();
  DemoOutcome outcome;
  outcome.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  if (!lines.summary().empty()) outcome.summary = parseSummary(lines.summary());
  return outcome;
}

MapFacts mapFacts(const json& exportedMap) {
  MapFacts facts;
  facts.regions = exportedMap["regions"].size();
  facts.gateways = exportedMap["gateways"].size();
  facts.graphNodes = exportedMap["graph"]["nodes"].size();
  facts.graphEdges = exportedMap["graph"]["edges"].size();
  for (const json& g : exportedMap["gateways"]) {
    facts.neutralised += g["neutralised"].get<bool>() ? 1 : 0;
    facts.gatewayClasses.push_back(g["label"].get<std::string>());
  }
  for (const json& r : exportedMap["regions"]) {
    facts.areaM2 += r["area"].get<double>();
    if (!r["name"].get<std::string>().empty()) facts.regionNames.push_back(r["name"].get<std::string>());
  }
  facts.gatewayClasses = sorted(facts.gatewayClasses);
  facts.regionNames = sorted(facts.regionNames);
  return facts;
}

json toJson(const MapFacts& f) {
  return {{"regions", f.regions},       {"gateways", f.gateways},         {"neutralised", f.neutralised},
          {"graphNodes", f.graphNodes}, {"graphEdges", f.graphEdges},     {"gatewayClasses", f.gatewayClasses},
          {"regionNames", f.regionNames}, {"areaM2", f.areaM2}};
}

MapFacts mapFactsFromJson(const json& saved) {
  MapFacts f;
  f.regions = saved.at("regions").get<std::size_t>();
  f.gateways = saved.at("gateways").get<std::size_t>();
  f.neutralised = saved.at("neutralised").get<std::size_t>();
  f.graphNodes = saved.at("graphNodes").get<std::size_t>();
  f.graphEdges = saved.at("graphEdges").get<std::size_t>();
  f.gatewayClasses = saved.at("gatewayClasses").get<std::vector<std::string>>();
  f.regionNames = saved.at("regionNames").get<std::vector<std::string>>();
  f.areaM2 = saved.at("areaM2").get<double>();
  return f;
}

}  // namespace rgnav::testing
