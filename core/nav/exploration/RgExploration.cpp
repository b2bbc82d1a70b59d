// Region-by-region exploration (RgExploration.h; thesis chapter 7: "each region should first be
// completely explored before traversing any new gateway. Gateways that have not yet been traversed
// can be stored on a stack ... visit these gateways in a breadth first manner"). Deliberate
// differences from the thesis, which leaves the strategy to future work: the untraversed gateways
// wait in a queue, not a stack, since breadth first is what the thesis asks for, and are taken
// region by region (the regions they were found from, first-in first-out), the nearest of a
// region's first; a frontier at an open gateway is the gateway's (see
// ExplorationTargets.h), a gateway is driven through to a point just past its line that the route
// planner accepts, and a frontier is also the current region's when the current region's
// freespace holds its viewpoint (where a lower region's freespace overlaps the current one).
#include "core/nav/exploration/RgExploration.h"

#include <algorithm>
#include <limits>
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

// The region on the side of a traversed gateway that was unknown when it was driven to: the side
// that is not `from`, or (both were unknown) the side whose crossing point lies nearer `far`.
RegionId regionBeyond(const GatewayView& g, RegionId from, const Eigen::Vector2d& far) {
  if (!from.isNone()) return g.sideA == from ? g.sideB : g.sideA;
  const auto distance = [&](std::size_t side) {
    const std::size_t c = g.sideCrossings[side];
    return c < g.crossingPoints.size() ? (g.crossingPoints[c] - far).norm() : std::numeric_limits<double>::infinity();
  };
  return distance(0) <= distance(1) ? g.sideA : g.sideB;
}

// The reachable frontier nearest by driving distance, if any.
std::optional<ExplorationGoal> nearestFrontier(const std::vector<Frontier>& frontiers, Reachability& reach,
                                               const std::string& why) {
  std::vector<Eigen::Vector2d> points;
  for (const Frontier& f : frontiers) points.push_back(f.viewpoint);
  const auto best = reach.nearest(points);
  if (!best) return std::nullopt;
  return frontierGoal(frontiers[best->index], best->lengthM, why);
}

}  // namespace

RgExploration::RgExploration(const ExplorationConfig& config) : config_(config) { validate(config_); }

ExplorationGoal RgExploration::next(const ExplorationInput& input, const PathLength& pathLength) {
  const Eigen::Vector2d robot(input.robot.x, input.robot.y);
  const Survey now = survey(input, config_, frontierFailures_);
  const std::vector<OpenGateway>& open = now.open;
  const std::vector<Frontier>& frontiers = now.frontiers;

  // The queue: traversed (or vanished, neutralised) gateways leave it, new open ones join its end.
  std::erase_if(queue_, [&](GatewayId id) {
    return std::none_of(open.begin(), open.end(), [&](const OpenGateway& g) { return g.id == id; });
  });
  for (const OpenGateway& g : open)
    if (seen_.insert(g.id).second) {
      queue_.push_back(g.id);
      foundIn_[g.id] = input.currentRegion;
    }

  // The gateway last driven to, once traversed, names the region to complete.
  if (entering_ && std::none_of(open.begin(), open.end(), [&](const OpenGateway& g) { return g.id == *entering_; })) {
    for (const GatewayView& g : input.map.gateways)
      if (g.id == *entering_ && !g.neutralised) completing_ = regionBeyond(g, enteringFrom_, enteringFar_);
    entering_.reset();
  }

  Reachability reach(pathLength, robot);

  // 1. The current region's frontiers, then those of the region entered last.
  for (const RegionId region : {input.currentRegion, completing_}) {
    const auto view = std::find_if(input.map.regions.begin(), input.map.regions.end(),
                                   [&](const RegionView& r) { return r.summary.id == region; });
    if (region.isNone() || view == input.map.regions.end()) continue;
    std::vector<Frontier> own;
    for (const Frontier& f : frontiers)
      if (ofRegion(f, *view)) {
        own.push_back(f);
        own.back().region = region;
      }
    const std::string why = region == input.currentRegion ? "completing the current region"
                                                          : "completing the region entered last";
    if (auto goal = nearestFrontier(own, reach, why)) return *goal;
  }
  completing_ = RegionId{};

  // 2. Breadth first: the gateways found from the region whose gateways were found first, the
  // nearest of them by driving distance. One that cannot be driven through leaves the queue; one
  // with no drive point candidate yet waits in it (ExplorationTargets.h). One
  // whose drive point the robot stands at was not reported traversed: counted as a failure (the
  // kernel may lag, so it stays queued until it failed maxGoalFailures times) and passed over.
  std::vector<RegionId> levels;
  for (const GatewayId id : queue_)
    if (std::find(levels.begin(), levels.end(), foundIn_[id]) == levels.end()) levels.push_back(foundIn_[id]);
  for (const RegionId level : levels) {
    std::vector<const OpenGateway*> group;
    std::vector<Eigen::Vector2d> points;
    std::vector<GatewayId> dropped;
    for (const GatewayId id : queue_) {
      if (foundIn_[id] != level) continue;
      const OpenGateway& g = *std::find_if(open.begin(), open.end(), [&](const OpenGateway& o) { return o.id == id; });
      if (g.drivePoints.empty()) continue;  // no target yet; its frontier leads the robot to look
      group.push_back(&g);
      points.push_back(g.drivePoints.front());
    }
    const auto best = reach.nearest(points, [&](std::size_t i) -> std::optional<Eigen::Vector2d> {
      const auto point = drivePoint(*group[i], reach);
      if (!point) {
        dropped.push_back(group[i]->id);
      } else if ((*point - robot).norm() <= kSameGoalM) {
        if (++gatewayFailures_[group[i]->id] >= config_.maxGoalFailures) dropped.push_back(group[i]->id);
        return std::nullopt;
      }
      return point;
    });
    std::erase_if(queue_, [&](GatewayId id) { return std::find(dropped.begin(), dropped.end(), id) != dropped.end(); });
    if (!best) continue;
    const OpenGateway& g = *group[best->index];
    entering_ = g.id;
    enteringFrom_ = g.known;
    enteringFar_ = g.far;
    std::ostringstream reason;
    reason.precision(3);
    reason << "no reachable frontier left in region " << input.currentRegion << ": breadth first through untraversed gateway "
           << g.id << " found from region " << level << " (nearest of " << group.size() << ", " << queue_.size()
           << " queued) to " << text(best->goal) << ", " << best->lengthM << " m away";
    return {ExplorationGoal::Kind::Gateway, best->goal, RegionId{}, g.id, reason.str()};
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
