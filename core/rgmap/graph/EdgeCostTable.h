// EdgeCostTable: what the robot has learned about the edges of the RG Graph (thesis 5.4), kept by
// stable edge identity so that it survives every rebuild of the graph. Costs are in metres.
//   - An edge's cost starts at its Euclidean length (the length of the straight line between its
//     crossing points, the lower bound of every cost).
//   - Traversal (ours: the thesis only says costs change with measured distance and time): a
//     traversal that covered lengthM in timeS counts as max(lengthM, timeS * nominalSpeedMps), so a
//     segment driven slower than the nominal speed (clutter, people, waiting) costs as much as the
//     distance the robot would have covered in that time. The edge's base cost is the running
//     mean of these values: the plain mean of the first traversalMemory traversals, then an
//     exponential mean with weight 1/traversalMemory, so the cost follows a changing environment.
//   - Doors (thesis 5.4): each time a door is found blocked, doorBlockedM is added to its edge's
//     cost; each time it is found open, doorOpenM (<= 0) is added. Deliberate difference: the
//     accumulated door offset never goes below zero, i.e. the thesis' lower bound "the real
//     distance" is the edge's base cost (measured, or Euclidean when never measured), so an open
//     door undoes earlier blocked observations but never makes the door cheaper than it has been
//     measured. doorExtraM raises the lower bound of every door edge, as the thesis suggests to make
//     paths prefer hallway gateways to doors (0 by default: no preference).
// cost = max(base, Euclidean length + door extra) + door offset, never below the Euclidean length.
#pragma once

#include <cstddef>
#include <map>

#include "core/rgmap/graph/RgGraphKeys.h"

namespace rgnav {

struct EdgeCostConfig {
  double nominalSpeedMps = 0.5;    // converts traversal time into length (half the robot's 1 m/s)
  std::size_t traversalMemory = 10;  // traversals in the plain mean before it turns exponential
  double doorBlockedM = 30.0;      // added when a door is found blocked
  double doorOpenM = -30.0;        // added when a door is found open; <= 0
  double doorExtraM = 0.0;         // door edges never cost less than their length plus this
};

template <class V>
void describe(V& v, EdgeCostConfig& c) {
  v.field("nominal_speed_mps", c.nominalSpeedMps);
  v.field("traversal_memory", c.traversalMemory);
  v.field("door_blocked_m", c.doorBlockedM);
  v.field("door_open_m", c.doorOpenM);
  v.field("door_extra_m", c.doorExtraM);
}

// Throws ConfigError naming the first value out of range (non-finite values, a non-positive
// speed, a zero memory, doorBlockedM <= 0, doorOpenM > 0, doorExtraM < 0).
void validate(const EdgeCostConfig& config);

struct TraversalStats {
  double meanM = 0.0;       // running mean of the traversal values (see above)
  std::size_t count = 0;    // traversals recorded
};

class EdgeCostTable {
 public:
  // Throws ConfigError for a bad configuration.
  explicit EdgeCostTable(const EdgeCostConfig& config = {});

  // One traversal of `edge` that covered lengthM in timeS (0 when the time was not measured).
  // Throws InvalidArgumentError for a negative or non-finite length or time.
  void recordTraversal(const EdgeKey& edge, double lengthM, double timeS);

  // One observation of the door of gateway g: traversable (open) or not (blocked).
  void recordDoorState(GatewayId g, bool traversable);

  // The cost of `edge` given its Euclidean length; door edges are the gateway edges of doors.
  // Throws InvalidArgumentError for a negative or non-finite length.
  double cost(const EdgeKey& edge, double lengthM, bool doorEdge) const;

  const EdgeCostConfig& config() const { return config_; }

  // The learned state, for checkpoints and displays; entries for edges that are no longer in the
  // graph are kept (harmless, and they apply again should the edge come back).
  const std::map<EdgeKey, TraversalStats>& traversals() const { return traversals_; }
  const std::map<GatewayId, double>& doorOffsets() const { return doorOffsets_; }

  // Restore learned state from a checkpoint. Throw InvalidArgumentError for a negative or
  // non-finite value, or a zero count.
  void restoreTraversal(const EdgeKey& edge, const TraversalStats& stats);
  void restoreDoorOffset(GatewayId g, double offsetM);

 private:
  EdgeCostConfig config_;
  std::map<EdgeKey, TraversalStats> traversals_;
  std::map<GatewayId, double> doorOffsets_;  // >= 0
};

}  // namespace rgnav
