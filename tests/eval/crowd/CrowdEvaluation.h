// CrowdEvaluation: what `rgctl eval crowd` and `rgctl faulttest motion` share: their options, the
// preparation (the world, the office RG map made once in process and kept in a cache folder, the
// seeded goals), the server set, and the summary line
//   crowd: goals=… reached=… robot_collisions=… person_bumps=… mean_speed_mps=…
// with the collision counters from the simulator's health.
#pragma once

#include <boost/program_options.hpp>
#include <string>
#include <vector>

#include "core/rgmap/kernel/RgMapState.h"
#include "core/sim/LoadedWorld.h"
#include "tests/eval/crowd/CrowdGoals.h"
#include "tests/eval/crowd/CrowdRun.h"
#include "tests/eval/crowd/CrowdSet.h"

namespace rgnav {

struct CrowdEvaluationOptions {
  std::string world = "config/worlds/office.yaml";
  std::string simConfig = "config/sim/default.yaml";
  std::string models = "config/gateways/gateway-hmms.txt";
  std::string plannerConfig = "config/modules/pathplanning.yaml";
  std::string mapCache = "out/crowd";  // the office RG map's checkpoint, made once
  Pose2D start{1.5, 7.0, 0.0};  // the main hallway's west end, facing east
  int people = 8;
  CrowdGoalOptions goals;
  CrowdRunOptions run;

  void addTo(boost::program_options::options_description& description);
};

struct PreparedCrowd {
  LoadedWorld world;
  Pose2D start;
  RgMapState map;
  std::vector<Eigen::Vector2d> goals;
};

// Loads the world, takes the RG map from the cache (or makes it and fills the cache) and draws
// the goals among those the route planner reaches on the map. Prints what it does to stderr.
PreparedCrowd prepareCrowd(const CrowdEvaluationOptions& options);

CrowdSetOptions crowdSetOptions(const CrowdEvaluationOptions& options, const PreparedCrowd& prepared);

struct SimulatorCounters {
  std::uint64_t robotCollisions = 0;
  std::uint64_t personBumps = 0;
};
// From the simulator's health (its Laser object's status).
SimulatorCounters simulatorCounters(const ClientSettings& settings);

// The summary line (no newline).
std::string crowdLine(const CrowdOutcome& outcome, const SimulatorCounters& counters);

}  // namespace rgnav
