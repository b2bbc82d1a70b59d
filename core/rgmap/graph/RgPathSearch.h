// Global path planning on the RG Graph (thesis 5.4): A* search over the crossing points with the
// current edge costs and the Euclidean distance to the goal as heuristic (admissible and
// consistent, since no edge costs less than its Euclidean length). Start and goal are places in
// regions; they join the search as temporary nodes linked to every crossing point of their region
// at Euclidean cost, and to each other directly when they share a region. The result is the list
// of crossing points, which in pairs belong to the same region or the same gateway, with the
// edges between them (a neutralised gateway's two crossing points have both kinds).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/rgmap/graph/RgGraph.h"

namespace rgnav {

struct RgPlace {
  RegionId region;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // global frame, metres
};

struct RgPath {
  std::vector<RgNode> crossings;  // in driving order; empty when start and goal share a region
                                  // (no route through crossing points beats the straight line)
  std::vector<EdgeKey> edges;     // between consecutive crossings (crossings.size() - 1 of them)
  double costM = 0.0;             // total cost, start and goal links included
  double lengthM = 0.0;           // total Euclidean length of the same route
};

// The cheapest path from start to goal. Throws InvalidArgumentError for a region that is not in
// the graph or a non-finite position, NotAvailableError when no path connects them.
RgPath findPath(const RgGraph& graph, const RgPlace& start, const RgPlace& goal);

}  // namespace rgnav
