// One BARN world in lock-step (see BarnRun.h).
#include "tests/eval/barn/BarnRun.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "core/nav/avoidance/MaplessNavigator.h"
#include "core/sim/LoadedWorld.h"

namespace rgnav {

namespace {

constexpr double kTopSpeedMps = 2.0;  // the benchmark's optimal time: reference length at 2 m/s

}  // namespace

BarnResult runBarnWorld(const std::string& worldYaml, const BarnSetup& setup) {
  const LoadedWorld world = loadWorld(worldYaml);
  if (!world.task || !world.task->referencePathLength)
    throw ConfigError(worldYaml + ": no navigation task with reference_path_length_m");
  const NavigationTask& task = *world.task;
  BarnResult result;
  result.name = std::filesystem::path(worldYaml).stem().string();
  result.optimalSeconds = *task.referencePathLength / kTopSpeedMps;

  Simulation sim(world.grid, setup.sim, task.start);
  LowLevelDrive drive(setup.drive);
  // The Collision Avoidance times chains as the drive will: within the reference limits.
  MaplessNavigator navigator(setup.avoidance, setup.sim.robot.footprint, referenceLimits(setup.drive));
  // The odometry frame starts at the start pose: the goal is where the task puts it.
  navigator.setGoal(task.goal);
  const double start = sim.time();
  std::optional<DriveChain> pending;
  while (sim.time() - start < setup.timeLimitS) {
    const SimulationStep step = sim.step();
    if (step.collided) {
      result.collided = true;
      break;
    }
    if (std::hypot(step.truePose.x - task.goal.x, step.truePose.y - task.goal.y) <= setup.goalRadiusM) {
      result.success = true;
      break;
    }
    if (step.scan) {
      const RobotState state{step.odometry.stamp, step.odometry.pose, step.odometry.translationalVelocity,
                             step.odometry.rotationalVelocity};
      const AvoidanceDecision decision = navigator.onScan(*step.scan, state);
      if (decision.chain) pending = decision.chain;
      if (decision.stopNow) {
        pending.reset();
        drive.stop();
      }
      result.blocked += decision.action == AvoidanceAction::Blocked;
      if (setup.trace && decision.action != AvoidanceAction::Keep)
        std::printf("# %s t=%.2f pose=(%.2f %.2f %.2f) v=%.2f targets=%zu %s: %s%s\n", result.name.c_str(),
                    sim.time() - start, state.pose.x, state.pose.y, state.pose.theta, state.velocity,
                    navigator.avoidance().targets().size(), toString(decision.action).c_str(), decision.reason.c_str(),
                    decision.chain ? (" length=" + std::to_string(decision.chain->chain.length())).c_str() : "");
    }
    // A chain reaches the drive at its start time, as from a module one planning latency away.
    if (pending && step.odometry.stamp >= pending->startTime - 1e-9) {
      drive.setChain(*pending);
      pending.reset();
    }
    sim.command(drive.tick(step.odometry, step.odometry.stamp));
  }
  result.seconds = sim.time() - start;
  result.timedOut = !result.success && !result.collided;
  if (result.success)
    result.score = result.optimalSeconds /
                   std::clamp(result.seconds, 2.0 * result.optimalSeconds, 8.0 * result.optimalSeconds);
  return result;
}

}  // namespace rgnav
