// The mapping chain as a test cluster, and its finished map (see MappingSet.h).
#include "tests/fault/MappingSet.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "core/config/ShippedConfig.h"
#include "core/supervision/SetConfig.h"
#include "tests/support/cluster/Interruption.h"

namespace fs = std::filesystem;

namespace rgnav::testing {

std::vector<ClusterModule> mappingSet(const std::string& log, const std::string& models, const std::string& speed) {
  return {{"LogPlayback", {TestCluster::program("rgnav-carmen-playback"), "--log", log, "--speed", speed}, {"Laser", "Base"}},
          {"ScanMapper", {TestCluster::program("rgnav-scanmapper"), "--config", TestCluster::moduleConfig("scanmapper")},
           {"ScanMapper"},
           {"LogPlayback"},
           "max_restarts: 1000"},
          {"GatewayDetection",
           {TestCluster::program("rgnav-gatewaydetection"), "--config", TestCluster::moduleConfig("gatewaydetection"),
            "--models", models},
           {"GatewayDetection"},
           {"LogPlayback"},
           "max_restarts: 1000"},
          {"RGMappingKernel",
           {TestCluster::program("rgnav-rgmappingkernel"), "--config", TestCluster::moduleConfig("rgmappingkernel")},
           {"RGMappingKernel"},
           {"ScanMapper", "GatewayDetection"},
           "max_restarts: 1000"}};
}

void waitForEndOfMap(TestCluster& cluster, double limitSeconds) {
  RgMappingKernelClient kernel(cluster.clientSettings());
  const auto giveUp = std::chrono::steady_clock::now() + std::chrono::duration<double>(limitSeconds);
  while (!kernel.summary().endOfData) {
    if (std::chrono::steady_clock::now() > giveUp) throw std::runtime_error("the map was not finished in time");
    sleepUntilOrInterrupted(std::chrono::steady_clock::now() + std::chrono::milliseconds(100));
  }
}

std::vector<ClusterModule> demoSet() { return shippedSetModules("sets/demo-mapping.yaml"); }

std::vector<ClusterModule> shippedSetModules(const std::string& relative) {
  const std::string setFile = shippedConfigFile(relative);
  const std::string root = fs::path(setFile).parent_path().parent_path().parent_path().string();
  const SetConfig set = loadSetConfig(setFile, {{"RGNAV_BIN", fs::path(TestCluster::program("rgnav-sim")).parent_path().string()}, {"RGNAV_ROOT", root}}, root);
  std::vector<ClusterModule> modules;
  for (const ModuleSpec& m : set.modules) {
    std::vector<std::string> command = m.command;
    const auto exportRoot = std::find(command.begin(), command.end(), "--export-root");
    if (exportRoot != command.end()) command.erase(exportRoot, std::min(exportRoot + 2, command.end()));
    modules.push_back({m.name, command, m.objects, m.after, "max_restarts: 1000"});
  }
  return modules;
}

nlohmann::json finishedMap(TestCluster& cluster, double limitSeconds, const std::string& name) {
  waitForEndOfMap(cluster, limitSeconds);
  return exportedMap(cluster, name);
}

nlohmann::json exportedMap(TestCluster& cluster, const std::string& name) {
  RgMappingKernelClient kernel(cluster.clientSettings());
  kernel.exportMap("", name, false);
  std::ifstream in(cluster.dir() + "/run/exports/" + name + ".rgmap.json");
  return nlohmann::json::parse(in);
}

}  // namespace rgnav::testing
