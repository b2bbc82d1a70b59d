// FramedQuadtreePlanner: A* over the framed quadtree with lazily generated edges, then smoothing
// (see the header).
#include "core/nav/planning/FramedQuadtreePlanner.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/PathSmoothing.h"
#include "core/raster/DistanceField.h"

namespace rgnav {

namespace {

std::string pointName(const Eigen::Vector2d& p) {
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ")";
  return out.str();
}

// A free cell the point lies in or on the border of, preferring the cell below-left of grid lines.
std::optional<CellIndex> freeCellAt(const OccupancyGrid& grid, const Eigen::Vector2d& p) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return std::nullopt;
  const double fx = std::floor(p.x()), fy = std::floor(p.y());
  if (fx < -1.0 || fy < -1.0 || fx > grid.width() || fy > grid.height()) return std::nullopt;
  const int col = static_cast<int>(fx), row = static_cast<int>(fy);
  for (int dc = 0; dc >= (fx == p.x() ? -1 : 0); --dc)
    for (int dr = 0; dr >= (fy == p.y() ? -1 : 0); --dr)
      if (!grid.blocked({col + dc, row + dr})) return CellIndex{col + dc, row + dr};
  return std::nullopt;
}

double polylineLength(const std::vector<Eigen::Vector2d>& points) {
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) length += (points[i] - points[i - 1]).norm();
  return length;
}

}  // namespace

void validate(const FramedQuadtreePlannerConfig& config) {
  if (!std::isfinite(config.wallCostDistanceM) || config.wallCostDistanceM < 0.0)
    throw ConfigError("framed-quadtree planner: wallCostDistanceM must be finite and >= 0");
  if (!std::isfinite(config.wallCostWeight) || config.wallCostWeight < 0.0)
    throw ConfigError("framed-quadtree planner: wallCostWeight must be finite and >= 0");
}

FramedQuadtreePlanner::FramedQuadtreePlanner(const OccupancyGrid& grid, FramedQuadtreePlannerConfig config)
    : grid_(grid), config_((validate(config), config)), tree_(grid) {
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
      nodeCost_.push_back(cellCost_[static_cast<std::size_t>(c.row) * grid.width() + c.col]);
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
  if (++search_ == 0) {  // the stamp wrapped: forget every old search
    std::fill(state_.begin(), state_.end(), NodeState{});
    search_ = 1;
  }
  const std::int32_t startQuad = tree_.quadOf(*startCell), goalQuad = tree_.quadOf(*goalCell);
  const bool costs = !nodeCost_.empty();
  const auto cellCost = [&](CellIndex c) { return cellCost_[static_cast<std::size_t>(c.row) * grid_.width() + c.col]; };
  const float startCost = costs ? cellCost(*startCell) : 0.0f, goalCost = costs ? cellCost(*goalCell) : 0.0f;
  const auto position = [&](std::int32_t id) -> const Eigen::Vector2d& {
    return id == startId ? start : id == goalId ? goal : nodeCentres_[static_cast<std::size_t>(id)];
  };
  const auto costOf = [&](std::int32_t id) -> float {
    return id == startId ? startCost : id == goalId ? goalCost : nodeCost_[static_cast<std::size_t>(id)];
  };
  const auto later = [](const Open& a, const Open& b) { return a.f > b.f || (a.f == b.f && a.g < b.g); };

  heap_.clear();
  CellUnitPath path;
  const auto relax = [&](std::int32_t from, double fromG, std::int32_t to) {
    NodeState& s = state_[static_cast<std::size_t>(to)];
    if (s.seen == search_ && s.closed == search_) return;
    const Eigen::Vector2d& p = position(to);
    double step = (p - position(from)).norm();
    if (costs) step *= 1.0 + 0.5 * (costOf(from) + costOf(to));
    const double g = fromG + step;
    if (s.seen == search_ && s.g <= g) return;
    s = {g, from, search_, 0};
    heap_.push_back({g + (goal - p).norm(), g, to});
    std::push_heap(heap_.begin(), heap_.end(), later);
  };
  const auto relaxFrame = [&](std::int32_t from, double fromG, std::int32_t quad) {
    const FramedQuadtree::Quad& q = tree_.quads()[static_cast<std::size_t>(quad)];
    for (std::int32_t n = q.firstNode; n < q.firstNode + q.nodeCount; ++n)
      if (n != from) relax(from, fromG, n);
    if (quad == goalQuad) relax(from, fromG, goalId);
  };

  state_[static_cast<std::size_t>(startId)] = {0.0, -1, search_, 0};
  heap_.push_back({(goal - start).norm(), 0.0, startId});
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const Open top = heap_.back();
    heap_.pop_back();
    NodeState& s = state_[static_cast<std::size_t>(top.node)];
    if (s.closed == search_ || top.g > s.g) continue;
    s.closed = search_;
    ++path.expansions;
    if (top.node == goalId) break;
    if (top.node == startId) {
      relaxFrame(startId, top.g, startQuad);
      continue;
    }
    const std::int32_t quad = tree_.nodeQuad(top.node);
    relaxFrame(top.node, top.g, quad);
    const CellIndex c = tree_.nodeCell(top.node);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const std::int32_t n = tree_.nodeOf({c.col + dx, c.row + dy});
        if (n == FramedQuadtree::kNone || tree_.nodeQuad(n) == quad) continue;
        // A diagonal step between cell centres is free unless it squeezes between two blocked
        // cells (segmentFree's rule at a grid vertex).
        if (dx != 0 && dy != 0 && grid_.blocked({c.col + dx, c.row}) && grid_.blocked({c.col, c.row + dy})) continue;
        relax(top.node, top.g, n);
      }
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
