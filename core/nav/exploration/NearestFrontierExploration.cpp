// The nearest-frontier baseline (NearestFrontierExploration.h; Yamauchi 1997). Deliberate
// difference: the RG map's freespace ends at a door the robot has not passed (the kernel cuts a
// region's freespace there), so the frontier there is never seen beyond from the region; the
// baseline's candidates are the frontiers not at open gateways and the open gateways' drive
// points (ExplorationTargets.h), the nearest by driving distance taken, whatever its kind.
#include "core/nav/exploration/NearestFrontierExploration.h"

#include <sstream>

#include "core/nav/exploration/ExplorationTargets.h"

namespace rgnav {

NearestFrontierExploration::NearestFrontierExploration(const ExplorationConfig& config) : config_(config) {
  validate(config_);
}

ExplorationGoal NearestFrontierExploration::next(const ExplorationInput& input, const PathLength& pathLength) {
  const Eigen::Vector2d robot(input.robot.x, input.robot.y);
  const ExplorationGrid grid = ExplorationGrid::fromMap(input.map, config_.grid);
  const std::vector<OpenGateway> open = openGateways(input.map, grid, robot);
  const std::vector<Frontier> frontiers =
      candidateFrontiers(findFrontiers(grid, config_.frontier, config_.robotRadiusM), open, robot, frontierFailures_,
                         config_.maxGoalFailures);
  Reachability reach(pathLength, robot);
  std::vector<Eigen::Vector2d> points;
  for (const Frontier& f : frontiers) points.push_back(f.viewpoint);
  std::vector<GatewayId> gateways;
  // A gateway's candidate farthest beyond its line stands for it (planned only if it is among the
  // nearest, so that many open gateways do not cost a plan each).
  for (const OpenGateway& g : open) {
    const std::vector<Eigen::Vector2d> candidates = drivePointCandidates(g, grid, config_.robotRadiusM);
    if (candidates.empty() || failuresAt(frontierFailures_, candidates.front()) >= config_.maxGoalFailures) continue;
    if ((candidates.front() - robot).norm() <= kSameGoalM) {
      countFailure(frontierFailures_, candidates.front());
      continue;
    }
    points.push_back(candidates.front());
    gateways.push_back(g.id);
  }
  const auto best = reach.nearest(points);
  if (!best) return {ExplorationGoal::Kind::Done, robot, RegionId{}, GatewayId{}, "no reachable frontier left"};
  std::ostringstream reason;
  reason.precision(3);
  if (best->first < frontiers.size()) {
    const Frontier& f = frontiers[best->first];
    reason << "nearest frontier: region " << f.region << " (" << f.lengthM() << " m), viewpoint " << best->second
           << " m away";
    return {ExplorationGoal::Kind::Frontier, f.viewpoint, f.region, GatewayId{}, reason.str()};
  }
  const GatewayId id = gateways[best->first - frontiers.size()];
  reason << "nearest frontier: beyond untraversed gateway " << id << ", " << best->second << " m away";
  return {ExplorationGoal::Kind::Gateway, points[best->first], RegionId{}, id, reason.str()};
}

void NearestFrontierExploration::failed(const ExplorationGoal& goal) { countFailure(frontierFailures_, goal.point); }

}  // namespace rgnav
