// mapRoomTourOnServerSet: one map of the room evaluation (issue 7, "rgctl eval rooms") made by the
// real server set, online: a TestCluster (temporary directory, free loopback ports, its own
// omniNames and watchdog; everything ended by PID afterwards) runs the Simulator module on the
// floor plan, driving its room tour in lock-step with its consumers, the ScanMapper, the
// GatewayDetection module (with the HMM file, if any) and the RG Mapping Kernel module, each with
// its own defaults, as `rgctl demo mapping` runs them. When the kernel has taken in the last scan, the
// final map is read through the kernel's client library (FinalMap.h: the same views the in-process
// run builds), the corrected poses through the ScanMapper's and the true poses through the
// simulator's GroundTruth object (evaluation only).
// What a server set does not tell: the scans each region holds (the kernel module serves counts,
// not IDs), so regionScans stays empty; the tour's rooms count as visited when the robot's true
// path entered them, against the rooms the planner can reach from the simulator's start.
#pragma once

#include <cstdint>
#include <string>

#include "core/raster/OccupancyGrid.h"
#include "core/sim/GroundTruth.h"
#include "tests/eval/rooms/MappingRun.h"

namespace rgnav {

struct ServerSetSetup {
  std::string models;         // HMM file for GatewayDetection; empty: narrow passages only
  std::string simConfig;      // simulator parameters (config/sim/*.yaml); empty: built-in
  std::uint64_t seed = 1;     // simulation seed
  double limitSeconds = 3600; // wall time one map may take
};

// `floorPlanPath` is the world the Simulator module loads; `grid` and `truth` are the same world
// loaded here, for the tour plan. Throws std::runtime_error when the map is not finished within
// the limit, and what the cluster and the client libraries throw.
MappingRun mapRoomTourOnServerSet(const std::string& floorPlanPath, const OccupancyGrid& grid, const GroundTruth& truth,
                                  const ServerSetSetup& setup);

}  // namespace rgnav
