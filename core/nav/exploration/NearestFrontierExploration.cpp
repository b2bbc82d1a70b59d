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
  const Survey now = survey(input, config_, frontierFailures_);
  const std::vector<Frontier>& frontiers = now.frontiers;
  Reachability reach(pathLength, robot);
  std::vector<Eigen::Vector2d> points;
  for (const Frontier& f : frontiers) points.push_back(f.viewpoint);
  // A gateway ranks by its candidate farthest beyond its line, and its drive point is planned only
  // if it is among the nearest, so that many open gateways do not cost plans each.
  std::vector<const OpenGateway*> gateways;
  for (const OpenGateway& g : now.open) {
    if (g.drivePoints.empty() || failuresAt(frontierFailures_, g.drivePoints.front()) >= config_.maxGoalFailures)
      continue;
    if ((g.drivePoints.front() - robot).norm() <= kSameGoalM) {
      countFailure(frontierFailures_, g.drivePoints.front());
      continue;
    }
    points.push_back(g.drivePoints.front());
    gateways.push_back(&g);
  }
  const auto best = reach.nearest(points, [&](std::size_t i) -> std::optional<Eigen::Vector2d> {
    if (i < frontiers.size()) return points[i];
    return drivePoint(*gateways[i - frontiers.size()], reach);
  });
  if (!best) return {ExplorationGoal::Kind::Done, robot, RegionId{}, GatewayId{}, "no reachable frontier left"};
  std::ostringstream reason;
  reason.precision(3);
  if (best->index < frontiers.size()) {
    const Frontier& f = frontiers[best->index];
    reason << "nearest frontier: region " << f.region << " (" << f.lengthM() << " m), viewpoint " << best->lengthM
           << " m away";
    return {ExplorationGoal::Kind::Frontier, f.viewpoint, f.region, GatewayId{}, reason.str()};
  }
  const GatewayId id = gateways[best->index - frontiers.size()]->id;
  reason << "nearest frontier: beyond untraversed gateway " << id << ", " << best->lengthM << " m away";
  return {ExplorationGoal::Kind::Gateway, best->goal, RegionId{}, id, reason.str()};
}

void NearestFrontierExploration::failed(const ExplorationGoal& goal) { countFailure(frontierFailures_, goal.point); }

}  // namespace rgnav
