// FramedQuadtreePlanner's fields: costs from every graph node to one target, and paths read off
// them (see FramedQuadtreePlanner.h).
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/CellPoints.h"
#include "core/nav/planning/FramedQuadtreePlanner.h"
#include "core/nav/planning/PathSmoothing.h"

namespace rgnav {

namespace {

constexpr double kUnreachable = std::numeric_limits<double>::infinity();

}  // namespace

FramedQuadtreePlanner::Field FramedQuadtreePlanner::fieldTo(const Eigen::Vector2d& target) const {
  const std::optional<CellIndex> cell = freeCellAt(grid_, target);
  if (!cell) throw GoalBlockedError("framed-quadtree planner: target " + pointName(target) + " is not in a free cell");
  Field field;
  field.target = target;
  field.targetQuad = tree_.quadOf(*cell);
  field.cost.assign(tree_.nodeCount(), kUnreachable);
  field.next.assign(tree_.nodeCount(), -1);
  field.targetCost = cellCostAt(*cell);
  const auto centre = [&](std::int32_t n) -> const Eigen::Vector2d& { return nodeCentres_[static_cast<std::size_t>(n)]; };

  using Item = std::pair<double, std::int32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  const FramedQuadtree::Quad& q = tree_.quads()[static_cast<std::size_t>(field.targetQuad)];
  for (std::int32_t n = q.firstNode; n < q.firstNode + q.nodeCount; ++n) {
    field.cost[static_cast<std::size_t>(n)] = moveCost((centre(n) - target).norm(), nodeCostAt(n), field.targetCost);
    open.push({field.cost[static_cast<std::size_t>(n)], n});
  }
  while (!open.empty()) {
    const double g = open.top().first;
    const std::int32_t u = open.top().second;
    open.pop();
    if (g > field.cost[static_cast<std::size_t>(u)]) continue;
    tree_.forEachNeighbour(u, [&](std::int32_t v) {
      const double through = g + moveCost((centre(v) - centre(u)).norm(), nodeCostAt(u), nodeCostAt(v));
      if (through < field.cost[static_cast<std::size_t>(v)]) {
        field.cost[static_cast<std::size_t>(v)] = through;
        field.next[static_cast<std::size_t>(v)] = u;
        open.push({through, v});
      }
    });
  }
  return field;
}

std::pair<double, std::int32_t> FramedQuadtreePlanner::fieldEntry(const Field& field, const Eigen::Vector2d& point) const {
  const std::optional<CellIndex> cell = freeCellAt(grid_, point);
  if (!cell) return {kUnreachable, -1};
  const float pointCost = cellCostAt(*cell);
  const auto edge = [&](const Eigen::Vector2d& to, float cost) { return moveCost((to - point).norm(), pointCost, cost); };
  std::pair<double, std::int32_t> best{kUnreachable, -1};
  const std::int32_t quad = tree_.quadOf(*cell);
  if (quad == field.targetQuad) best.first = edge(field.target, field.targetCost);
  const FramedQuadtree::Quad& q = tree_.quads()[static_cast<std::size_t>(quad)];
  for (std::int32_t n = q.firstNode; n < q.firstNode + q.nodeCount; ++n) {
    const double through = field.cost[static_cast<std::size_t>(n)] + edge(nodeCentres_[static_cast<std::size_t>(n)], nodeCostAt(n));
    if (through < best.first) best = {through, n};
  }
  return best;
}

std::optional<double> FramedQuadtreePlanner::costTo(const Field& field, const Eigen::Vector2d& point) const {
  const double cost = fieldEntry(field, point).first;
  if (!std::isfinite(cost)) return std::nullopt;
  return cost;
}

CellUnitPath FramedQuadtreePlanner::pathTo(const Field& field, const Eigen::Vector2d& point) const {
  const auto [cost, entry] = fieldEntry(field, point);
  if (!std::isfinite(cost))
    throw NoPathError("framed-quadtree planner: no path from " + pointName(point) + " to " + pointName(field.target));
  CellUnitPath path;
  path.points.push_back(point);
  for (std::int32_t n = entry; n != -1; n = field.next[static_cast<std::size_t>(n)])
    path.points.push_back(nodeCentres_[static_cast<std::size_t>(n)]);
  path.points.push_back(field.target);
  smoothPath(grid_, cellCost_, path.points);
  path.length = polylineLength(path.points);
  return path;
}

}  // namespace rgnav
