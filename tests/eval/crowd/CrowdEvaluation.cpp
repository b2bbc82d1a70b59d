// The crowd evaluation's options, preparation and summary (see CrowdEvaluation.h).
#include "tests/eval/crowd/CrowdEvaluation.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "clientlibs/common/ModuleClient.h"
#include "core/common/AtomicFile.h"
#include "core/nav/planning/KernelPlanningMap.h"
#include "core/nav/planning/RoutePlannerConfigYaml.h"
#include "core/rgmap/kernel/RgMapCodec.h"
#include "tests/eval/rooms/MappingPipeline.h"
#include "tests/eval/crowd/OfficeRgMap.h"

namespace po = boost::program_options;

namespace rgnav {
namespace {

// The cached map if the cache holds one, else the map made now (and cached).
RgMapState officeMap(const CrowdEvaluationOptions& o, const LoadedWorld& world) {
  const std::string file = o.mapCache + "/rgmap.state";
  const std::optional<std::string> text = readCheckpoint(file);
  const std::optional<std::string> journal = readCheckpoint(file + ".scans");
  if (text && journal) {
    std::cerr << "crowd: the RG map from " << file << std::endl;
    return deserializeRgMap(*text, *journal);
  }
  std::cerr << "crowd: mapping " << o.world << " along its room tour with true poses (once; cached in "
            << o.mapCache << ")" << std::endl;
  RgMapState map = mapWorldWithTruePoses(world, o.models);
  writeKernelCheckpoint(map, o.mapCache);
  return map;
}

std::uint64_t counter(const ModuleStatusInfo& status, const std::string& name) {
  const auto found = status.counters.find(name);
  if (found == status.counters.end())
    throw NotAvailableError("the simulator's health has no counter " + name);
  return found->second;
}

}  // namespace

void CrowdEvaluationOptions::addTo(po::options_description& d) {
  d.add_options()
      ("world", po::value(&world)->default_value(world), "world with ground-truth rooms")
      ("sim-config", po::value(&simConfig)->default_value(simConfig), "simulator parameters")
      ("models", po::value(&models)->default_value(models), "gateway HMMs for mapping the world")
      ("planner-config", po::value(&plannerConfig)->default_value(plannerConfig), "PathPlanning parameters (goals it can reach)")
      ("map-cache", po::value(&mapCache)->default_value(mapCache), "folder of the world's RG map checkpoint (made if missing)")
      ("start-x", po::value(&start.x)->default_value(start.x), "robot start, m")
      ("start-y", po::value(&start.y)->default_value(start.y), "robot start, m")
      ("start-theta", po::value(&start.theta)->default_value(start.theta), "robot start heading, rad")
      ("people", po::value(&people)->default_value(people), "people walking in the world")
      ("goals", po::value(&goals.count)->default_value(goals.count), "goals to drive")
      ("seed", po::value(&goals.seed)->default_value(goals.seed), "seed of the goals and the people")
      ("clearance", po::value(&goals.clearanceM)->default_value(goals.clearanceM), "goals this far from obstacles, m")
      ("spacing", po::value(&goals.minSpacingM)->default_value(goals.minSpacingM), "goals this far apart, m")
      ("tolerance", po::value(&run.toleranceM)->default_value(run.toleranceM), "reached: true pose this near, m")
      ("goal-timeout", po::value(&run.goalTimeoutS)->default_value(run.goalTimeoutS), "seconds per goal");
}

PreparedCrowd prepareCrowd(const CrowdEvaluationOptions& o) {
  PreparedCrowd p{loadWorld(o.world), o.start, {}, {}};
  if (!p.world.truth) throw ConfigError(o.world + ": no ground-truth rooms to put goals in");
  p.map = officeMap(o, p.world);
  // Goals the PathPlanning module can plan to on this map (as the module will: the same planner,
  // parameters and map), so that a goal counts against the motion, not against the map's extent.
  const RgMappingKernel kernel(shippedPipelineConfig().kernel, p.map);
  RoutePlanner planner(loadRoutePlannerConfig(o.plannerConfig));
  planner.setMap(planningMapOf(kernel));
  const auto reachable = [&](const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
    try {
      planner.plan({from.x(), from.y(), 0.0}, PlanGoal::at(to));
      return true;
    } catch (const Error&) {
      return false;
    }
  };
  p.goals = crowdGoals(p.world.grid, *p.world.truth, p.start, o.goals, reachable);
  return p;
}

CrowdSetOptions crowdSetOptions(const CrowdEvaluationOptions& o, const PreparedCrowd& p) {
  return {o.world, o.simConfig, p.start, o.people, o.goals.seed, ""};
}

SimulatorCounters simulatorCounters(const ClientSettings& settings) {
  ModuleClient simulator("Laser", settings);
  const ModuleStatusInfo status = simulator.status();
  return {counter(status, "robot_collisions"), counter(status, "person_bumps")};
}

std::string crowdLine(const CrowdOutcome& outcome, const SimulatorCounters& counters) {
  char line[256];
  std::snprintf(line, sizeof line, "crowd: goals=%zu reached=%zu robot_collisions=%llu person_bumps=%llu mean_speed_mps=%.3f",
                outcome.goals.size(), outcome.reached(), static_cast<unsigned long long>(counters.robotCollisions),
                static_cast<unsigned long long>(counters.personBumps), outcome.meanSpeedMps());
  return line;
}

}  // namespace rgnav
