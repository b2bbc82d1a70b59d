// One exploration in lock-step; see ExplorationRun.h.
#include "tests/eval/exploration/ExplorationRun.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/common/Errors.h"
#include "core/nav/exploration/Explorer.h"
#include "core/nav/exploration/PlannerPathLength.h"
#include "core/nav/grid/GridPlanner.h"
#include "core/sim/StartPose.h"

namespace rgnav {
namespace {

DriveOutcome outcomeOf(GoalDriveState state) {
  switch (state) {
    case GoalDriveState::Driving: return DriveOutcome::Driving;
    case GoalDriveState::Reached: return DriveOutcome::Reached;
    case GoalDriveState::Failed: return DriveOutcome::Failed;
    case GoalDriveState::Idle: break;
  }
  return DriveOutcome::None;
}

std::string metres(const std::optional<double>& m) {
  if (!m) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", *m);
  return text;
}

// Gateways of the map with a side whose region is not known (for the trace).
std::size_t oneSideUnknown(const PlanningMap& map) {
  return std::size_t(std::count_if(map.gateways.begin(), map.gateways.end(), [](const GatewayView& g) {
    return !g.neutralised && (g.sideA.isNone() || g.sideB.isNone());
  }));
}

}  // namespace

std::string explorationLine(const std::string& mapName, const ExplorationResult& result) {
  char line[512];
  std::snprintf(line, sizeof line, "exploration %s %s: seen_95_m=%s seen_99_m=%s rooms_found=%zu/%zu collisions=%llu time_s=%.1f",
                mapName.c_str(), result.strategy.c_str(), metres(result.seen95M).c_str(),
                metres(result.seen99M).c_str(), result.roomsFound, result.roomsReachable,
                static_cast<unsigned long long>(result.collisions), result.seconds);
  return line;
}

Pose2D startInFirstRoom(const OccupancyGrid& world, const GroundTruth& truth, double robotRadiusM) {
  GridPlannerConfig config;
  config.robotRadius = robotRadiusM;
  const GridPlanner planner(world, config);
  const Pose2D open = openestPose(world);
  const std::vector<bool> floor = planner.reachableFrom({open.x, open.y});
  // Per room, its cell on the floor farthest from any wall.
  std::vector<std::optional<CellIndex>> best(std::size_t(std::max(truth.roomCount, 0)));
  for (int row = 0; row < world.height(); ++row)
    for (int col = 0; col < world.width(); ++col) {
      const int room = truth.roomOf({col, row});
      if (room < 0 || !floor[rowMajor({col, row}, world.width())]) continue;
      std::optional<CellIndex>& b = best[std::size_t(room)];
      if (!b || planner.clearance().at({col, row}) > planner.clearance().at(*b)) b = CellIndex{col, row};
    }
  for (const std::optional<CellIndex>& cell : best)
    if (cell) {
      const WorldPoint p = world.center(*cell);
      return {p.x, p.y, 0.0};
    }
  throw InvalidArgumentError("no ground-truth room lies on the floor the robot can drive");
}

ExplorationResult runExploration(InProcessRobot& robot, TruthCoverage& coverage, const ExplorationSetup& setup) {
  Explorer explorer(makeExplorationStrategy(setup.strategy, setup.exploration), setup.exploration);
  ExplorationResult result;
  result.strategy = setup.strategy;
  const double start = robot.time();
  bool failureCounted = false;
  while (robot.time() - start < setup.timeLimitS) {
    const SimulationStep step = robot.step();
    if (!step.scan) continue;
    coverage.addScan(*step.scan);
    result.truePath.emplace_back(step.truePose.x, step.truePose.y);
    const double share = coverage.seenShare();
    if (!result.seen95M && share >= 0.95) result.seen95M = robot.pathM();
    if (!result.seen99M && share >= 0.99) result.seen99M = robot.pathM();
    if (!robot.mapped()) continue;  // no region yet: nothing to explore from
    if (robot.drive().state() == GoalDriveState::Failed && !failureCounted) {
      ++result.failedDrives;
      failureCounted = true;
      if (setup.trace)
        std::printf("# %s t=%.1f drive failed: %s\n", setup.strategy.c_str(), robot.time() - start,
                    robot.drive().reason().c_str());
    }
    const Pose2D pose = robot.pose();
    const PathLength pathLength = plannerPathLength(robot.planner(), pose);
    const ExplorationInput input{robot.planner().map(), pose, robot.kernel().state().current};
    const ExplorerStep next = explorer.update(input, outcomeOf(robot.drive().state()), robot.time() - start, pathLength);
    if (next.action == ExplorerStep::Action::Done) {
      if (setup.trace)
        std::printf("# %s t=%.1f done: %s\n", setup.strategy.c_str(), robot.time() - start, next.goal.reason.c_str());
      robot.cancelDrive();
      result.done = true;
      break;
    }
    if (next.action == ExplorerStep::Action::DriveTo) {
      if (setup.trace)
        std::printf("# %s t=%.1f path=%.1f seen=%.3f regions=%zu gateways=%zu one_side_unknown=%zu pose=(%.2f %.2f) "
                    "goal %s (%.2f %.2f): %s\n",
                    setup.strategy.c_str(), robot.time() - start, robot.pathM(), share, input.map.regions.size(),
                    input.map.gateways.size(), oneSideUnknown(input.map), pose.x, pose.y,
                    next.goal.kind == ExplorationGoal::Kind::Gateway ? "gateway" : "frontier", next.goal.point.x(),
                    next.goal.point.y(), next.goal.reason.c_str());
      robot.driveTo(PlanGoal::at(next.goal.point));
      failureCounted = false;
    }
  }
  result.seconds = robot.time() - start;
  result.pathM = robot.pathM();
  result.seenShare = coverage.seenShare();
  result.goals = explorer.goalsGiven();
  result.collisions = robot.simulation().robotCollisions();
  for (const RoomCoverage& room : coverage.rooms()) {
    result.roomsReachable += room.reachable();
    result.roomsFound += room.found();
  }
  return result;
}

}  // namespace rgnav
