// Test helper: the modules that make the robot go, for the High-Level Planning module's
// integration tests: the simulator in real time on the two-room world
// (tests/worlds/hallway_two_rooms.yaml) from the hallway's west end (1, 1) facing east, with
// noiseless odometry and range readings (so the odometry frame, the Collision Avoidance's map frame
// with pose source "odometry", stays the world frame), the Low-Level Drive, the Collision
// Avoidance and the High-Level Planning module (pose source scanmapper). No module reads the
// ground truth. The kernel and the PathPlanning module come from PlanningSet.h; the mapping
// modules (ScanMapper, GatewayDetection) from mappingModules().
#pragma once

#include <string>
#include <vector>

#include "tests/support/cluster/TestCluster.h"

namespace rgnav::testing {

// Writes the simulator's noiseless parameters into `dir`.
std::vector<ClusterModule> motionAndTasks(const std::string& dir);
// The ScanMapper and the GatewayDetection module following the simulator (the kernel follows them).
std::vector<ClusterModule> mappingModules();

}  // namespace rgnav::testing
