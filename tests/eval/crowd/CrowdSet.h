// CrowdSet: the server set of the crowd evaluation and the motion fault test, as a TestCluster
// (own omniNames and watchdog, free loopback ports, a temporary directory, torn down by PID): the
// simulator in real time on a world with walking people, the Low-Level Drive, the RG Mapping
// Kernel holding a given RG map (its checkpoint placed in its state directory before the start),
// the PathPlanning module on it, and the Collision Avoidance with the simulator's ground-truth
// pose as its pose source.
#pragma once

#include <memory>
#include <string>

#include "core/common/Pose2D.h"
#include "core/rgmap/kernel/RgMapState.h"
#include "tests/support/cluster/TestCluster.h"

namespace rgnav {

struct CrowdSetOptions {
  std::string world;      // the simulator's --world (relative: to the working directory)
  std::string simConfig;  // its --config
  Pose2D start;
  int people = 8;
  std::uint64_t seed = 1;
  std::string setYaml;    // extra top-level YAML of the set (e.g. faster restarts)
};

class CrowdSet {
 public:
  // Writes the kernel's checkpoint of `map` into the set's directory (nullptr: the kernel starts
  // without a map, so the PathPlanning module cannot plan); start() brings the set up.
  CrowdSet(const CrowdSetOptions& options, const RgMapState* map);

  void start();
  testing::TestCluster& cluster() { return *cluster_; }

 private:
  std::unique_ptr<testing::TestCluster> cluster_;
};

}  // namespace rgnav
