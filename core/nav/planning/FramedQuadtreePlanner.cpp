// FramedQuadtreePlanner: A* over the framed quadtree with lazily generated edges, then smoothing
// (see the header).
#include "core/nav/planning/FramedQuadtreePlanner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/CellPoints.h"
#include "core/nav/planning/PathSmoothing.h"
#include "core/raster/DistanceField.h"

namespace rgnav {

void validate(const FramedQuadtreePlannerConfig& config) {
  if (!std::isfinite(config.wallCostDistanceM) || config.wallCostDistanceM < 0.0)
    throw ConfigError("framed-quadtree planner: wallCostDistanceM must be finite and >= 0");
  if (!std::isfinite(config.wallCostWeight) || config.wallCostWeight < 0.0)
    throw ConfigError("framed-quadtree planner: wallCostWeight must be finite and >= 0");
}

FramedQuadtreePlanner::FramedQuadtreePlanner(const OccupancyGrid& grid, FramedQuadtreePlannerConfig config)
    : grid_(grid), config_((validate(config), config)), tree_(grid), lineOfSight_(grid), landmarks_(tree_, lineOfSight_) {
  nodeCentres_.reserve(tree_.nodeCount());
  for (std::size_t n = 0; n < tree_.nodeCount(); ++n) {
    const CellIndex c = tree_.nodeCell(static_cast<std::int32_t>(n));
    nodeCentres_.emplace_back(c.col + 0.5, c.row + 0.5);
  }
  if (config_.wallCostDistanceM > 0.0 && config_.wallCostWeight > 0.0) {
    // Distance from a cell centre to the nearest blocked cell's border, about half a cell less
    // than between the centres.
    const std::vector<float> squared = squaredDistanceToBlocked(grid);
    cellCost_.resize(squared.size());
    for (std::size_t i = 0; i < squared.size(); ++i) {
      const double metres = std::max(0.0, std::sqrt(double(squared[i])) - 0.5) * grid.resolution();
      cellCost_[i] = static_cast<float>(config_.wallCostWeight * std::max(0.0, 1.0 - metres / config_.wallCostDistanceM));
    }
    nodeCost_.reserve(tree_.nodeCount());
    for (std::size_t n = 0; n < tree_.nodeCount(); ++n) {
      const CellIndex c = tree_.nodeCell(static_cast<std::int32_t>(n));
      nodeCost_.push_back(cellCostAt(c));
    }
  }
}

CellUnitPath FramedQuadtreePlanner::plan(const Eigen::Vector2d& start, const Eigen::Vector2d& goal) const {
  const std::optional<CellIndex> startCell = freeCellAt(grid_, start);
  if (!startCell) throw StartBlockedError("framed-quadtree planner: start " + pointName(start) + " is not in a free cell");
  const std::optional<CellIndex> goalCell = freeCellAt(grid_, goal);
  if (!goalCell) throw GoalBlockedError("framed-quadtree planner: goal " + pointName(goal) + " is not in a free cell");

  const std::lock_guard lock(mutex_);
  const auto nodes = static_cast<std::int32_t>(tree_.nodeCount());
  const std::int32_t startId = nodes, goalId = nodes + 1;
  if (state_.size() != static_cast<std::size_t>(nodes) + 2) {
    state_.assign(static_cast<std::size_t>(nodes) + 2, NodeState{});
    search_ = 0;
  }
  if (frameRelaxed_.size() != tree_.quads().size()) frameRelaxed_.assign(tree_.quads().size(), FrameRelaxation{});
  if (++search_ == 0) {  // the stamp wrapped: forget every old search
    std::fill(state_.begin(), state_.end(), NodeState{});
    std::fill(frameRelaxed_.begin(), frameRelaxed_.end(), FrameRelaxation{});
    search_ = 1;
  }
  const std::int32_t startQuad = tree_.quadOf(*startCell), goalQuad = tree_.quadOf(*goalCell);
  const bool costs = !nodeCost_.empty();
  const float startCost = cellCostAt(*startCell), goalCost = cellCostAt(*goalCell);
  const auto position = [&](std::int32_t id) -> const Eigen::Vector2d& {
    return id == startId ? start : id == goalId ? goal : nodeCentres_[static_cast<std::size_t>(id)];
  };
  const auto costOf = [&](std::int32_t id) -> float {
    return id == startId ? startCost : id == goalId ? goalCost : nodeCostAt(id);
  };
  const auto later = [](const Open& a, const Open& b) { return a.f > b.f || (a.f == b.f && a.g < b.g); };
  const auto stateOf = [&](std::int32_t id) -> NodeState& { return state_[static_cast<std::size_t>(id)]; };
  const auto closed = [&](std::int32_t id) { return stateOf(id).closed == search_; };
  const auto edgeCost = [&](std::int32_t a, std::int32_t b) {
    return moveCost((position(b) - position(a)).norm(), costOf(a), costOf(b));
  };
  // The landmark distances of start and goal, through the frame of their quad.
  const auto landmarkDistances = [&](std::int32_t quad, const Eigen::Vector2d& p) {
    FramedQuadtreeLandmarks::Distances d;
    d.fill(FramedQuadtreeLandmarks::kUnreachable);
    const FramedQuadtree::Quad& q = tree_.quads()[static_cast<std::size_t>(quad)];
    for (std::int32_t n = q.firstNode; n < q.firstNode + q.nodeCount; ++n) {
      const double step = (nodeCentres_[static_cast<std::size_t>(n)] - p).norm();
      for (std::size_t l = 0; l < d.size(); ++l) d[l] = std::min(d[l], landmarks_.of(n)[l] + step);
    }
    return d;
  };
  const FramedQuadtreeLandmarks::Distances startLandmarks = landmarkDistances(startQuad, start);
  const FramedQuadtreeLandmarks::Distances goalLandmarks = landmarkDistances(goalQuad, goal);
  const auto heuristic = [&](std::int32_t id) {
    if (id == goalId) return 0.0;
    const double* d = id == startId ? startLandmarks.data() : landmarks_.of(id);
    return std::max((goal - position(id)).norm(), FramedQuadtreeLandmarks::lowerBound(d, goalLandmarks.data()));
  };
  // Queues a node with its g (its heuristic is computed once per search).
  const auto push = [&](std::int32_t id, double g) {
    heap_.push_back({g + stateOf(id).h, g, id});
    std::push_heap(heap_.begin(), heap_.end(), later);
  };
  const auto quadOf = [&](std::int32_t id) {
    return id == startId ? startQuad : id == goalId ? goalQuad : tree_.nodeQuad(id);
  };
  // Calls visit(n) for every graph neighbour n of node `id`, start and goal joined to the frame of
  // their quad (and to each other when they share it); the frame part only if `frame`.
  const auto forEachNeighbour = [&](std::int32_t id, bool frame, auto&& visit) {
    const std::int32_t quad = quadOf(id);
    if (id < nodes) tree_.forEachCellNeighbour(id, visit);
    if (!frame) return;
    if (id < nodes) {
      tree_.forEachFrameNeighbour(id, visit);
    } else {
      const FramedQuadtree::Quad& q = tree_.quads()[static_cast<std::size_t>(quad)];
      for (std::int32_t n = q.firstNode; n < q.firstNode + q.nodeCount; ++n) visit(n);
    }
    if (quad == goalQuad && id != goalId) visit(goalId);
    if (quad == startQuad && id != startId) visit(startId);
  };

  const bool anyAngle = !costs;  // Lazy Theta*; with wall costs plain A*, whose edges carry the costs
  heap_.clear();
  CellUnitPath path;
  stateOf(startId) = {0.0, heuristic(startId), -1, search_, 0};
  push(startId, 0.0);
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const Open top = heap_.back();
    heap_.pop_back();
    NodeState& s = stateOf(top.node);
    if (s.closed == search_ || top.g != s.g) continue;
    if (anyAngle && s.parent >= 0 && !lineOfSight_.free(position(s.parent), position(top.node))) {
      // Lazy Theta*: the assumed line of sight from the parent's parent is blocked; the best
      // expanded neighbour becomes the parent and the node waits its turn again with that g. Its
      // quad's frame is relaxed afresh at the next expansion there, which may offer less again.
      frameRelaxed_[static_cast<std::size_t>(quadOf(top.node))].search = 0;
      s.g = std::numeric_limits<double>::infinity();
      forEachNeighbour(top.node, true, [&](std::int32_t n) {
        if (!closed(n)) return;
        const double g = stateOf(n).g + edgeCost(n, top.node);
        if (g < s.g) {
          s.g = g;
          s.parent = n;
        }
      });
      // Still no worse than every queued node: expanded now, as queueing it would.
      if (!heap_.empty() && s.g + s.h > heap_.front().f) {
        push(top.node, s.g);
        continue;
      }
    }
    s.closed = search_;
    ++path.expansions;
    if (top.node == goalId) break;
    // Lazy Theta*: assume a line of sight from this node's parent; checked when `to` is expanded.
    const std::int32_t parent = anyAngle && s.parent >= 0 ? s.parent : top.node;
    // A quad's frame relaxed from the same parent before gets nothing new: the parent's g is final.
    FrameRelaxation& last = frameRelaxed_[static_cast<std::size_t>(quadOf(top.node))];
    const bool frame = last.search != search_ || last.parent != parent;
    last = {search_, parent};
    forEachNeighbour(top.node, frame, [&](std::int32_t to) {
      NodeState& t = stateOf(to);
      if (t.seen == search_ && t.closed == search_) return;
      const double g = stateOf(parent).g + edgeCost(parent, to);
      if (t.seen == search_ && t.g <= g) return;
      if (t.seen != search_) t = {0.0, heuristic(to), -1, search_, 0};
      t.g = g;
      t.parent = parent;
      push(to, g);
    });
  }
  if (state_[static_cast<std::size_t>(goalId)].closed != search_)
    throw NoPathError("framed-quadtree planner: no path from " + pointName(start) + " to " + pointName(goal));

  for (std::int32_t id = goalId; id != -1; id = state_[static_cast<std::size_t>(id)].parent)
    path.points.push_back(position(id));
  std::reverse(path.points.begin(), path.points.end());
  smoothPath(grid_, cellCost_, path.points);
  path.length = polylineLength(path.points);
  return path;
}

}  // namespace rgnav
