// Test helper: a server set for the PathPlanning module's integration and fault tests: the RG
// Mapping Kernel holding the map of the kernel tests' two-room tour (a hallway, x in [0, 12] and
// y in [0, 2], with room 1 behind door 11 and room 2 behind door 12 north of it;
// SyntheticTour.h), loaded from a checkpoint placed in its state directory before the start, as a
// restarted kernel loads its own, and the PathPlanning module planning on it. The kernel's inputs
// (ScanMapper, GatewayDetection) are not in the set: the map stays as loaded. Other tests add
// modules of their own (the High-Level Planning module's test: the simulator and the motion chain).
#pragma once

#include <memory>

#include "core/rgmap/kernel/RgMappingKernel.h"
#include "tests/support/cluster/TestCluster.h"

namespace rgnav::testing {

// The kernel (started without a map unless its checkpoint is placed) and the PathPlanning module,
// as set modules.
std::vector<ClusterModule> planningModules();

class PlanningSet {
 public:
  // `setYaml`: extra top-level YAML of the set (e.g. kFastBackoff); `more`: modules besides the
  // kernel and the PathPlanning module.
  explicit PlanningSet(const std::string& setYaml = "", std::vector<ClusterModule> more = {});

  TestCluster& cluster() { return *cluster_; }
  // The map the kernel holds (as loaded, before any change).
  const RgMappingKernel& map() const { return map_; }

 private:
  RgMappingKernel map_;
  std::unique_ptr<TestCluster> cluster_;
};

}  // namespace rgnav::testing
