// OfficeRgMap: the RG map the crowd evaluation plans on, made once in process: the simulator's
// standard room tour of the office (mapRoomTour, tests/eval/rooms) through the mapping chain
// (gateway detection -> RG Mapping Kernel) with the TRUE pose of every scan as its corrected pose,
// so the map frame is the world frame and the robot's ground-truth pose (the CAM's pose source in
// this evaluation) needs no alignment. In process rather than by running the demo's mapping set
// first: deterministic for the seed, no second server set to bring up and wait for, and no SLAM
// error between the map and the world that would blur what the evaluation measures (the motion).
// The kernel module loads the map as it loads its own checkpoint after a restart.
#pragma once

#include <string>

#include "core/rgmap/kernel/RgMappingKernel.h"
#include "core/sim/LoadedWorld.h"

namespace rgnav {

// Maps `world` (with ground truth) along its room tour. `models`: the gateway HMM file (empty or
// missing: narrow passages only).
RgMapState mapWorldWithTruePoses(const LoadedWorld& world, const std::string& models);

// Writes the kernel's checkpoint files (rgmap.state and its scan journal) into `stateDir`, the
// RG Mapping Kernel module's state directory.
void writeKernelCheckpoint(const RgMapState& state, const std::string& stateDir);

}  // namespace rgnav
