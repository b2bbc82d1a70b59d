// Map-less goal seeking on the sensed obstacle grid (see GoalSeeking.h).
#include "core/nav/avoidance/GoalSeeking.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "core/nav/grid/GridPlanner.h"
#include "core/nav/grid/PlanningErrors.h"
#include "core/nav/planning/TargetSpacing.h"

namespace rgnav {

namespace {

// How far from the planner's start or goal a traversable cell is looked for when the robot (or
// the goal) stands too close to an obstacle for the inflated disk.
constexpr double kSnapReachM = 0.6;

OccupancyGrid obstaclesOnly(const OccupancyGrid& obstacles) {
  OccupancyGrid grid(obstacles.width(), obstacles.height(), obstacles.resolution(), obstacles.origin(), Cell::Free);
  for (int row = 0; row < grid.height(); ++row)
    for (int col = 0; col < grid.width(); ++col)
      if (obstacles.at({col, row}) == Cell::Occupied) grid.set({col, row}, Cell::Occupied);
  return grid;
}

WorldPoint insideGrid(const OccupancyGrid& grid, WorldPoint p, double inset) {
  const WorldPoint o = grid.origin();
  return {std::clamp(p.x, o.x + inset, o.x + grid.width() * grid.resolution() - inset),
          std::clamp(p.y, o.y + inset, o.y + grid.height() * grid.resolution() - inset)};
}

// The traversable cell nearest to p within kSnapReachM.
std::optional<WorldPoint> nearestTraversable(const GridPlanner& planner, WorldPoint p) {
  const OccupancyGrid& grid = planner.grid();
  const auto centre = grid.cellOf(p);
  if (!centre) return std::nullopt;
  if (planner.traversable(*centre)) return p;
  const int reach = static_cast<int>(std::ceil(kSnapReachM / grid.resolution()));
  std::optional<CellIndex> best;
  int bestSquared = reach * reach + 1;
  for (int dr = -reach; dr <= reach; ++dr)
    for (int dc = -reach; dc <= reach; ++dc) {
      const CellIndex c{centre->col + dc, centre->row + dr};
      const int squared = dc * dc + dr * dr;
      if (squared < bestSquared && grid.contains(c) && planner.traversable(c)) {
        best = c;
        bestSquared = squared;
      }
    }
  if (!best) return std::nullopt;
  return grid.center(*best);
}

}  // namespace

GoalSeeking::GoalSeeking(const GoalSeekingConfig& config, const Footprint& footprint)
    : config_(config), footprint_(footprint) {
  validate(config);
  validate(footprint);
}

std::optional<std::vector<WorldPoint>> GoalSeeking::path(const OccupancyGrid& grid, WorldPoint from, WorldPoint goal,
                                                         double radius) const {
  const GridPlanner planner(grid, {radius, std::max(config_.comfortClearanceM, radius + grid.resolution()),
                                   config_.clearanceWeight});
  const auto start = nearestTraversable(planner, from);
  const auto end = nearestTraversable(planner, goal);
  if (!start || !end) return std::nullopt;
  try {
    std::vector<WorldPoint> points = planner.plan(*start, *end);
    points.front() = from;
    return points;
  } catch (const NoPathError&) {
    return std::nullopt;
  }
}

std::optional<std::vector<Pose2D>> GoalSeeking::plan(const OccupancyGrid& obstacles, const Pose2D& from,
                                                     WorldPoint goal, double extraMarginM) const {
  const OccupancyGrid grid = obstaclesOnly(obstacles);
  const double inscribed = footprint_.inscribedRadius();
  const WorldPoint inside = insideGrid(grid, goal, kSnapReachM);
  auto points = path(grid, {from.x, from.y}, inside, inscribed + config_.inflationMarginM + extraMarginM);
  if (!points && extraMarginM > 0.0) points = path(grid, {from.x, from.y}, inside, inscribed + config_.inflationMarginM);
  if (!points && config_.inflationMarginM > 0.0) points = path(grid, {from.x, from.y}, inside, inscribed);
  if (!points) return std::nullopt;
  if (std::hypot(inside.x - goal.x, inside.y - goal.y) > 1e-9) points->push_back(goal);
  std::vector<Eigen::Vector2d> polyline;
  for (const WorldPoint& p : *points)
    if (polyline.empty() || (polyline.back() - Eigen::Vector2d(p.x, p.y)).norm() > 1e-6) polyline.emplace_back(p.x, p.y);
  if (polyline.size() < 2) return std::vector<Pose2D>{{goal.x, goal.y, from.theta}};
  return targetsAlong(polyline, config_.targetMinSpacingM, config_.targetMaxSpacingM, std::nullopt);
}

}  // namespace rgnav
