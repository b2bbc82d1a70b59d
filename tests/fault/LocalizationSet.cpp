// The localization fault test's server set (see LocalizationSet.h).
#include "tests/fault/LocalizationSet.h"

#include <filesystem>

#include "core/common/AtomicFile.h"

namespace rgnav::testing {

std::unique_ptr<TestCluster> localizationSet(const std::string& log, const AnchoredRun& run) {
  auto cluster = std::make_unique<TestCluster>(
      std::vector<ClusterModule>{
          {"LogPlayback",
           {TestCluster::program("rgnav-carmen-playback"), "--log", log, "--speed", "max"},
           {"Laser", "Base"}},
          {"RGMappingKernel",
           {TestCluster::program("rgnav-rgmappingkernel"), "--config", TestCluster::moduleConfig("rgmappingkernel")},
           {"RGMappingKernel"}},
          {"Localization",
           {TestCluster::program("rgnav-localization"), "--config", TestCluster::moduleConfig("localization"),
            "--start-at-odometry", "--start-sigma-xy", "0.05", "--start-sigma-theta", "0.035",
            "--checkpoint-interval", "0.2"},
           {"Localization"},
           {"LogPlayback", "RGMappingKernel"},
           "max_restarts: 1000"}},
      "defaults: {backoff_initial_s: 0.05, backoff_max_s: 0.4}");
  const std::string dir = cluster->dir() + "/run/state/RGMappingKernel";
  std::filesystem::create_directories(dir);
  writeFileAtomically(dir + "/rgmap.state", run.kernelState);
  writeFileAtomically(dir + "/rgmap.state.scans", run.kernelJournal);
  return cluster;
}

}  // namespace rgnav::testing
