// RgExploration: region-by-region exploration (thesis chapter 7, "future work" there): the robot
// completes the region it is in before it traverses any new gateway, i.e. it drives to the
// frontiers of the current region (nearest by driving distance first) until none is left that can
// be reached; then it takes the next untraversed gateway from its queue and drives through it.
// Untraversed gateways: gateways of the map with a side whose region is not known yet (the far
// side unexplored), queued in the order they are first seen, each with the region the robot was in
// then (the region it was found from). "Breadth first" over gateways found in different regions:
// the gateways found from the region whose gateways were found first are all taken before those
// found from regions entered later, deeper in the building, as a breadth-first search over the RG
// graph visits the nearer regions first; among one region's, the nearest by driving distance
// first (breadth first leaves the order of siblings open; nearest first saves the drive back
// along a hallway to its first door). A gateway the robot cannot reach, or that is traversed
// meanwhile (both sides known), leaves the queue; one it has not seen through yet (no floor past
// its line to drive to) waits, and its frontier is the region's. The region entered through the gateway last
// driven to is completed next even when the kernel's current region is another (its traversal
// reached the kernel late, and the robot, sent on meanwhile, stepped back through the door). When
// the queue is empty the frontiers of every region are taken, nearest first (a region left before
// it was complete, say because a door was closed). Done when no reachable frontier and no gateway
// is left.
#pragma once

#include <deque>
#include <map>
#include <optional>
#include <set>

#include "core/nav/exploration/ExplorationStrategy.h"
#include "core/nav/exploration/Frontiers.h"

namespace rgnav {

class RgExploration : public ExplorationStrategy {
 public:
  explicit RgExploration(const ExplorationConfig& config);
  std::string name() const override { return "rg"; }
  ExplorationGoal next(const ExplorationInput& input, const PathLength& pathLength) override;
  void failed(const ExplorationGoal& goal) override;

  // The untraversed gateways, in the order they were first seen.
  const std::deque<GatewayId>& queue() const { return queue_; }

 private:
  ExplorationConfig config_;
  std::deque<GatewayId> queue_;
  std::set<GatewayId> seen_;
  std::map<GatewayId, RegionId> foundIn_;  // the current region when a gateway was first seen
  std::map<GatewayId, std::size_t> gatewayFailures_;
  std::vector<std::pair<Eigen::Vector2d, std::size_t>> frontierFailures_;  // failed viewpoints
  // The gateway last driven to, until it is traversed, with its known side's region and its far
  // crossing point; then the region beyond it, until that has no reachable frontier left.
  std::optional<GatewayId> entering_;
  RegionId enteringFrom_;
  Eigen::Vector2d enteringFar_ = Eigen::Vector2d::Zero();
  RegionId completing_;
};

}  // namespace rgnav
