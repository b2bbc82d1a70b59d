// runBarnWorld: one world of the BARN benchmark (../shared/data/planning/barn/SOURCES.md) driven
// in process, in lock-step: the simulator (the Jackal's rectangle, limits and 270-degree laser)
// steps 20 times a simulated second, the Low-Level Drive commands it on every step from its
// odometry, and the MaplessNavigator (laser obstacle grid, goal seeking, Collision Avoidance)
// decides on every scan, knowing only the goal (never the map). The run ends at the goal (within
// 1 m), at the first collision or after the time limit. Benchmark score: success * OT /
// clip(T, 2 OT, 8 OT), OT = reference path length / 2 m/s.
#pragma once

#include <string>

#include "core/nav/avoidance/CollisionAvoidanceConfig.h"
#include "core/nav/motion/LowLevelDrive.h"
#include "core/sim/Simulation.h"

namespace rgnav {

struct BarnSetup {
  SimulationConfig sim;
  CollisionAvoidanceConfig avoidance;
  LowLevelDriveConfig drive;
  double timeLimitS = 100.0;
  double goalRadiusM = 1.0;
  bool trace = false;  // print every decision that is not Keep
};

struct BarnResult {
  std::string name;
  bool success = false;
  bool collided = false;
  bool timedOut = false;
  double seconds = 0.0;         // simulated, to the end of the run
  double optimalSeconds = 0.0;  // OT
  double score = 0.0;
  std::size_t blocked = 0;      // times the Collision Avoidance reported blocked
};

// Throws FileError / FormatError / ConfigError for a world that cannot be read or has no task
// with a reference path length.
BarnResult runBarnWorld(const std::string& worldYaml, const BarnSetup& setup);

}  // namespace rgnav
