// The kernel with the two-room map and the PathPlanning module as a set (see PlanningSet.h).
#include "tests/integration/PlanningSet.h"

#include <filesystem>

#include "core/common/AtomicFile.h"
#include "core/rgmap/export/testing/ExportedFloor.h"
#include "core/rgmap/kernel/RgMapCodec.h"

namespace rgnav::testing {

std::vector<ClusterModule> planningModules() {
  return {
      {"RGMappingKernel",
       {TestCluster::program("rgnav-rgmappingkernel"), "--config", TestCluster::moduleConfig("rgmappingkernel")},
       {"RGMappingKernel"}},
      {"PathPlanning",
       {TestCluster::program("rgnav-pathplanning"), "--config", TestCluster::moduleConfig("pathplanning")},
       {"PathPlanning"},
       {"RGMappingKernel"}}};
}

PlanningSet::PlanningSet(const std::string& setYaml, std::vector<ClusterModule> more)
    : map_(twoRoomMap()) {
  std::vector<ClusterModule> modules = planningModules();
  modules.insert(modules.end(), more.begin(), more.end());
  cluster_ = std::make_unique<TestCluster>(std::move(modules), setYaml);
  const std::string dir = cluster_->dir() + "/run/state/RGMappingKernel";
  std::filesystem::create_directories(dir);
  writeFileAtomically(dir + "/rgmap.state", serializeRgMap(map_.state()));
  writeFileAtomically(dir + "/rgmap.state.scans", scanJournalLines(map_.state()));
}

}  // namespace rgnav::testing
