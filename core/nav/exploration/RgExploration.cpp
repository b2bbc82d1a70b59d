// Region-by-region exploration (RgExploration.h; thesis chapter 7: "each region should first be
// completely explored before traversing any new gateway. Gateways that have not yet been traversed
// can be stored on a stack ... visit these gateways in a breadth first manner"). Deliberate
// differences from the thesis, which leaves the strategy to future work: the untraversed gateways
// wait in a first-in first-out queue across regions, not a stack, since breadth first is what the
// thesis asks for; a frontier at an open gateway is the gateway's (see
// ExplorationTargets.h), a gateway is driven through to a point just past its line that the route
// planner accepts, and a frontier is also the current region's when the current region's
// freespace holds its viewpoint (where a lower region's freespace overlaps the current one).
#include "core/nav/exploration/RgExploration.h"

#include <algorithm>
#include <sstream>

#include "core/lines/ScanPoints.h"
#include "core/nav/exploration/ExplorationTargets.h"

namespace rgnav {
namespace {

std::string text(const Eigen::Vector2d& p) {
  std::ostringstream out;
  out.precision(3);
  out << "(" << p.x() << ", " << p.y() << ")";
  return out.str();
}

ExplorationGoal frontierGoal(const Frontier& f, double lengthM, const std::string& why) {
  std::ostringstream reason;
  reason.precision(3);
  reason << why << ": frontier of region " << f.region << " (" << f.lengthM() << " m) at " << text(f.middle)
         << ", viewpoint " << lengthM << " m away";
  return {ExplorationGoal::Kind::Frontier, f.viewpoint, f.region, GatewayId{}, reason.str()};
}

// Whether the frontier is the region's to complete: its cells' region (the lowest of those whose
// freespaces overlap there), or the region's freespace holds its viewpoint. A room entered
// through a door its hallway saw into before the door was known overlaps the hallway's freespace,
// and the room's frontiers there are the room's; their cells may lie just beyond the room's own
// freespace, where the hallway saw farther, so the viewpoint decides, well inside.
bool ofRegion(const Frontier& f, const RegionView& region) {
  return f.region == region.summary.id ||
         region.freespace.isFreeAt(transformPoint(inverse(region.summary.frame), f.viewpoint));
}

// The reachable frontier nearest by driving distance, if any.
std::optional<ExplorationGoal> nearestFrontier(const std::vector<Frontier>& frontiers, Reachability& reach,
                                               const std::string& why) {
  std::vector<Eigen::Vector2d> points;
  for (const Frontier& f : frontiers) points.push_back(f.viewpoint);
  const auto best = reach.nearest(points);
  if (!best) return std::nullopt;
  return frontierGoal(frontiers[best->first], best->second, why);
}

}  // namespace

RgExploration::RgExploration(const ExplorationConfig& config) : config_(config) { validate(config_); }

ExplorationGoal RgExploration::next(const ExplorationInput& input, const PathLength& pathLength) {
  const Eigen::Vector2d robot(input.robot.x, input.robot.y);
  const ExplorationGrid grid = ExplorationGrid::fromMap(input.map, config_.grid);
  const std::vector<OpenGateway> open = openGateways(input.map, grid, robot);

  // The queue: traversed (or vanished, neutralised) gateways leave it, new open ones join its end.
  std::erase_if(queue_, [&](GatewayId id) {
    return std::none_of(open.begin(), open.end(), [&](const OpenGateway& g) { return g.id == id; });
  });
  for (const OpenGateway& g : open)
    if (seen_.insert(g.id).second) queue_.push_back(g.id);

  Reachability reach(pathLength, robot);
  const std::vector<Frontier> frontiers =
      candidateFrontiers(findFrontiers(grid, config_.frontier, config_.robotRadiusM), open, robot, frontierFailures_,
                         config_.maxGoalFailures);

  // 1. The current region's frontiers.
  std::vector<Frontier> here;
  const auto current = std::find_if(input.map.regions.begin(), input.map.regions.end(),
                                    [&](const RegionView& r) { return r.summary.id == input.currentRegion; });
  if (current != input.map.regions.end())
    for (const Frontier& f : frontiers)
      if (ofRegion(f, *current)) {
        here.push_back(f);
        here.back().region = current->summary.id;
      }
  if (auto goal = nearestFrontier(here, reach, "completing the current region")) return *goal;

  // 2. The oldest open gateway that can be driven through; one that cannot leaves the queue. One
  // whose drive point the robot stands at was not reported traversed: counted as a failure (the
  // kernel may lag, so it stays queued until it failed maxGoalFailures times).
  for (auto it = queue_.begin(); it != queue_.end();) {
    const auto g = std::find_if(open.begin(), open.end(), [&](const OpenGateway& o) { return o.id == *it; });
    const auto point = drivePoint(*g, grid, config_.robotRadiusM, reach);
    if (!point || (*point - robot).norm() <= kSameGoalM) {
      if (!point || ++gatewayFailures_[*it] >= config_.maxGoalFailures) {
        it = queue_.erase(it);
      } else {
        ++it;
      }
      continue;
    }
    std::ostringstream reason;
    reason << "no reachable frontier left in region " << input.currentRegion << ": through untraversed gateway " << *it;
    if (!g->known.isNone()) reason << " of region " << g->known;
    reason << " (" << queue_.size() << " queued) to " << text(*point);
    return {ExplorationGoal::Kind::Gateway, *point, RegionId{}, *it, reason.str()};
  }

  // 3. Frontiers left behind in other regions.
  if (auto goal = nearestFrontier(frontiers, reach, "no untraversed gateway left")) return *goal;
  return {ExplorationGoal::Kind::Done, robot, RegionId{}, GatewayId{},
          "no reachable frontier and no untraversed gateway left"};
}

void RgExploration::failed(const ExplorationGoal& goal) {
  if (goal.kind == ExplorationGoal::Kind::Frontier) countFailure(frontierFailures_, goal.point);
  if (goal.kind != ExplorationGoal::Kind::Gateway) return;
  if (++gatewayFailures_[goal.gateway] >= config_.maxGoalFailures) std::erase(queue_, goal.gateway);
}

}  // namespace rgnav
