// FramedQuadtreeLandmarks: the ALT heuristic (Goldberg & Harrelson, "Computing the Shortest Path:
// A* Search Meets Graph Theory", SODA 2005) for the framed-quadtree planner: from a few landmark
// nodes, the any-angle distance to every node, computed once per grid by a Dijkstra search with
// Lazy Theta*'s parent shortcuts (the planner's own search without a goal). By the triangle
// inequality |d(L, a) - d(L, b)| bounds the distance between a and b from below, and around
// obstacles (rooms behind doors, mazes) far more tightly than the straight line. Differs from the
// paper: its distances are graph distances; these are any-angle ones, so that the bound stays
// (up to Theta*'s small excess over the true Euclidean distance) below the any-angle lengths the
// planner searches for, and it keeps the paths close to Euclidean. A last Dijkstra pass along the
// graph edges lowers any distance above a neighbour's plus the edge, so that along every edge the
// bound changes by at most the edge's length (consistency), which the planner's length guarantee
// needs.
// Landmarks are picked farthest-first (each the node farthest from those before), starting from
// the far end of the largest connected component; other components get none and are left to the
// straight-line bound.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/nav/planning/FramedQuadtree.h"
#include "core/nav/planning/LineOfSight.h"

namespace rgnav {

class FramedQuadtreeLandmarks {
 public:
  static constexpr std::size_t kCount = 8;
  using Distances = std::array<double, kCount>;  // to each landmark; infinity where unreachable
  static constexpr double kUnreachable = std::numeric_limits<double>::infinity();

  // `lineOfSight` is over the grid `tree` was built from.
  FramedQuadtreeLandmarks(const FramedQuadtree& tree, const LineOfSight& lineOfSight);

  const double* of(std::int32_t node) const { return &distances_[static_cast<std::size_t>(node) * kCount]; }
  // The largest |d(L, a) - d(L, b)| over the landmarks that reach both; 0 if none does.
  static double lowerBound(const double* a, const double* b) {
    double bound = 0.0;
    for (std::size_t l = 0; l < kCount; ++l)
      if (a[l] != kUnreachable && b[l] != kUnreachable) bound = std::max(bound, a[l] > b[l] ? a[l] - b[l] : b[l] - a[l]);
    return bound;
  }

 private:
  std::vector<double> distances_;  // node-major: kCount per node
};

}  // namespace rgnav
