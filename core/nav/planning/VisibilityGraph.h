// VisibilityGraph: the exact Euclidean shortest path between two points of an OccupancyGrid under
// the shared collision model (SegmentVisibility.h), the physical limit against which the planners
// of thesis 5.4 are measured (ratio_to_euclid in `rgctl eval planning`).
// The shortest path bends only at convex obstacle corners: grid vertices where exactly one of the
// four cells around is blocked (where two diagonal ones are blocked it cannot pass at all). It is
// found by A* with the Euclidean heuristic over the tangent ("sparse") visibility graph of these
// corners (Oh & Leong, "Edge N-Level Sparse Visibility Graphs", SoCS 2017; the tangent graph of
// Liu & Arimoto 1992): an edge is kept only where the line through it does not cut into the
// obstacle at either corner, and a corner is left only along edges that keep the path taut around
// it. Unlike the paper, the graph is not built up front: a corner's neighbours are found the first
// time the search expands it and cached for later queries (a mutable cache: not thread-safe).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <vector>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct EuclideanPath {
  std::vector<Eigen::Vector2d> points;  // cell units, start first, goal last
  double length = 0.0;
};

class VisibilityGraph {
 public:
  // The grid must outlive this object and not change; blocked = not Cell::Free or outside.
  explicit VisibilityGraph(const OccupancyGrid& grid);
  ~VisibilityGraph();
  VisibilityGraph(const VisibilityGraph&) = delete;
  VisibilityGraph& operator=(const VisibilityGraph&) = delete;

  // The exact shortest path between two points (cell units) under segmentFree
  // (SegmentVisibility.h). Throws StartBlockedError / GoalBlockedError for a point not in or on the
  // border of a free cell, NoPathError when they are not connected.
  EuclideanPath shortestPath(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;

  // The number of convex corners (graph vertices).
  std::size_t vertexCount() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rgnav
