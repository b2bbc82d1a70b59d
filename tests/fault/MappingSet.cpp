// The mapping chain as a test cluster, and its finished map (see MappingSet.h).
#include "tests/fault/MappingSet.h"

#include <chrono>
#include <fstream>
#include <stdexcept>

#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "tests/support/cluster/Interruption.h"

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

nlohmann::json finishedMap(TestCluster& cluster, double limitSeconds, const std::string& name) {
  waitForEndOfMap(cluster, limitSeconds);
  RgMappingKernelClient kernel(cluster.clientSettings());
  kernel.exportMap("", name, false);
  std::ifstream in(cluster.dir() + "/run/exports/" + name + ".rgmap.json");
  return nlohmann::json::parse(in);
}

}  // namespace rgnav::testing
