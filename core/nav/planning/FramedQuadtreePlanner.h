// FramedQuadtreePlanner: region path planning of thesis 5.4 — A* over the graph of a FramedQuadtree
// (figure 5.7 right), optional node costs that keep the path away from walls (figure 5.8 right),
// then smoothing (figure 5.8 left). Points are in cell units (SegmentVisibility.h) and every
// straight move obeys segmentFree(), the collision model all planners of this library share.
// Graph: a node's neighbours are the other frame cells of its quad (a straight segment inside a
// free square, any direction) and its 8 neighbouring cells in other quads; start and goal join as
// temporary nodes linked to the frame of their quad (and to each other when they share one).
// Search: without wall costs, Lazy Theta* (Nash, Koenig & Tovey, "Lazy Theta*: Any-Angle Path
// Planning and Path Length Analysis in 3D", AAAI 2010) over that graph: a node takes its
// predecessor's parent as its own, and the line of sight is checked (segmentFree) when it is
// expanded; if blocked, its best expanded neighbour becomes the parent and the node is queued
// again with that g unless it still leads the queue. So a node is expanded only with the length of
// a real free path, and since a shortcut is never longer than the two edges it replaces, that
// length is never above the node's distance in the graph (the A* argument with a consistent
// heuristic). With wall
// costs, plain A*: a shortcut would skip the costs of the nodes it passes. The heuristic is the
// larger of the straight-line distance and the landmark bound (FramedQuadtreeLandmarks.h), both
// consistent along the graph's edges. Segments are checked with LineOfSight (segmentFree with a
// fast path through open space).
// Smoothing (PathSmoothing.h): string pulling and bends moved onto obstacle corners, each step
// only shortening the path. The graph's optimum is never longer than the octile optimum (a run of
// octile moves inside a free quad is no shorter than the straight segment between its ends), so
// neither is the returned path.
// Differs from the thesis: start and goal are joined to their quad's whole frame instead of being
// moved to cell centres afterwards; the search is any-angle with a landmark heuristic; the bends
// snap to obstacle corners.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/nav/planning/FramedQuadtree.h"
#include "core/nav/planning/FramedQuadtreeLandmarks.h"
#include "core/nav/planning/LineOfSight.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct FramedQuadtreePlannerConfig {
  double wallCostDistanceM = 0.0;  // node cost falls linearly from wallCostWeight at an obstacle to 0 at this distance (metres, via grid.resolution()); 0 turns wall costs off
  double wallCostWeight = 1.0;     // extra cost per metre of path at distance 0 (>= 0)
};
// Throws ConfigError for negative or non-finite values.
void validate(const FramedQuadtreePlannerConfig&);

struct CellUnitPath {                   // points in cell units (SegmentVisibility.h)
  std::vector<Eigen::Vector2d> points;  // start first (exactly the start given), goal last (exactly the goal given)
  double length = 0.0;                  // Euclidean length of the polyline, cell units
  std::size_t expansions = 0;           // search nodes expanded
};

class FramedQuadtreePlanner {
 public:
  // Builds the framed quadtree of `grid` (which must outlive the planner), its landmark distances
  // and distance field. Throws ConfigError for an invalid config.
  FramedQuadtreePlanner(const OccupancyGrid& grid, FramedQuadtreePlannerConfig config = {});
  // Any start/goal point inside (or on the border of) a free cell, cell units. Throws
  // StartBlockedError / GoalBlockedError (point not in a free cell) and NoPathError (not
  // connected), with a message naming the point. Calls on one planner are serialised.
  CellUnitPath plan(const Eigen::Vector2d& start, const Eigen::Vector2d& goal) const;
  const FramedQuadtree& tree() const { return tree_; }

  // Costs from every graph node to one point, for many paths to the same place (the route
  // planner's paths to a crossing point): Dijkstra over the graph with the search's edge costs
  // (wall costs included), the point joined to its quad's frame (FramedQuadtreeField.cpp).
  // Without wall costs these are graph distances, not Lazy Theta*'s shorter any-angle ones.
  struct Field {
    Eigen::Vector2d target = Eigen::Vector2d::Zero();
    std::int32_t targetQuad = -1;
    float targetCost = 0.0f;           // the wall cost at the target
    std::vector<double> cost;          // per graph node; infinity where the target is not reachable
    std::vector<std::int32_t> next;    // per graph node: the next node towards the target; -1: the target
  };
  // Throws GoalBlockedError for a target not in a free cell.
  Field fieldTo(const Eigen::Vector2d& target) const;
  // The cost of the cheapest path from `point` to the field's target (cell units, wall costs
  // included); none for a point in no free cell or not connected to the target.
  std::optional<double> costTo(const Field& field, const Eigen::Vector2d& point) const;
  // That path, smoothed as plan() smooths: `point` first, the target last. Throws NoPathError where
  // costTo has none.
  CellUnitPath pathTo(const Field& field, const Eigen::Vector2d& point) const;

 private:
  // The wall cost of a cell and of a graph node (0 without wall costs).
  float cellCostAt(CellIndex c) const {
    return cellCost_.empty() ? 0.0f : cellCost_[static_cast<std::size_t>(c.row) * grid_.width() + c.col];
  }
  float nodeCostAt(std::int32_t node) const {
    return nodeCost_.empty() ? 0.0f : nodeCost_[static_cast<std::size_t>(node)];
  }
  // The cost of a straight move of `length` between places of wall costs a and b: the length
  // weighed by the mean of the two (thesis 5.4, figure 5.8 right). Without wall costs, the length.
  static double moveCost(double length, float a, float b) { return length * (1.0 + 0.5 * (a + b)); }
  // The cost from `point` to a field's target and the first node of that path (its quad's frame
  // node with the least cost through it; -1 when it goes straight to the target in the same quad);
  // infinite cost where there is none.
  std::pair<double, std::int32_t> fieldEntry(const Field& field, const Eigen::Vector2d& point) const;

  struct NodeState {
    double g = 0.0;
    double h = 0.0;  // the heuristic to the goal
    std::int32_t parent = -1;
    std::uint32_t seen = 0;    // search stamp: g and parent are valid
    std::uint32_t closed = 0;  // search stamp: expanded
  };
  struct Open {
    double f;
    double g;
    std::int32_t node;
  };

  struct FrameRelaxation {  // a quad's frame last relaxed in search `search` from `parent`
    std::uint32_t search = 0;
    std::int32_t parent = -1;
  };

  const OccupancyGrid& grid_;
  FramedQuadtreePlannerConfig config_;
  FramedQuadtree tree_;
  LineOfSight lineOfSight_;
  FramedQuadtreeLandmarks landmarks_;
  std::vector<Eigen::Vector2d> nodeCentres_;  // per graph node
  std::vector<float> nodeCost_;               // per graph node, extra cost per cell of path (empty: off)
  std::vector<float> cellCost_;               // per cell, the same field for smoothing (empty: off)
  mutable std::mutex mutex_;
  mutable std::vector<NodeState> state_;  // graph nodes, then start and goal
  mutable std::vector<Open> heap_;
  mutable std::vector<FrameRelaxation> frameRelaxed_;  // per quad
  mutable std::uint32_t search_ = 0;
};

}  // namespace rgnav
