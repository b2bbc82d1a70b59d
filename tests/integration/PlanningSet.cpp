// The kernel with the two-room map and the PathPlanning module as a set (see PlanningSet.h).
#include "tests/integration/PlanningSet.h"

#include <filesystem>

#include "core/common/AtomicFile.h"
#include "core/rgmap/export/testing/ExportedFloor.h"
#include "core/rgmap/kernel/RgMapCodec.h"

namespace rgnav::testing {

PlanningSet::PlanningSet(const std::string& setYaml)
    : map_(twoRoomMap()),
      cluster_(std::make_unique<TestCluster>(
          std::vector<ClusterModule>{
              {"RGMappingKernel",
               {TestCluster::program("rgnav-rgmappingkernel"), "--config", TestCluster::moduleConfig("rgmappingkernel")},
               {"RGMappingKernel"}},
              {"PathPlanning",
               {TestCluster::program("rgnav-pathplanning"), "--config", TestCluster::moduleConfig("pathplanning")},
               {"PathPlanning"},
               {"RGMappingKernel"}}},
          setYaml)) {
  const std::string dir = cluster_->dir() + "/run/state/RGMappingKernel";
  std::filesystem::create_directories(dir);
  writeFileAtomically(dir + "/rgmap.state", serializeRgMap(map_.state()));
  writeFileAtomically(dir + "/rgmap.state.scans", scanJournalLines(map_.state()));
}

}  // namespace rgnav::testing
