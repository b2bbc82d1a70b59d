// GridPlanner: start/goal checks, search, shortcutting, and conversion to world waypoints.
#include "core/nav/grid/GridPlanner.h"

#include <cmath>
#include <string>

#include "core/common/ValueChecks.h"
#include "core/nav/grid/PathShortcut.h"
#include "core/nav/grid/PlanningErrors.h"

namespace rgnav {

namespace {

std::string describe(WorldPoint p) {
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}

}  // namespace

void validate(const GridPlannerConfig& config) {
  requirePositive(config.robotRadius, "planner robot radius");
  requirePositive(config.comfortClearance, "planner comfort clearance");
  requireNonNegative(config.clearanceWeight, "planner clearance weight");
}

GridPlanner::GridPlanner(const OccupancyGrid& grid, const GridPlannerConfig& config)
    : config_((validate(config), config)), clearance_(grid) {}

GridSearch GridPlanner::search() const {
  const double minimum = config_.robotRadius + grid().resolution() * M_SQRT1_2;
  return GridSearch(clearance_, {minimum, config_.comfortClearance, config_.clearanceWeight});
}

CellIndex GridPlanner::startCell(WorldPoint start) const {
  const auto cell = grid().cellOf(start);
  if (!cell || !traversable(*cell)) {
    throw StartBlockedError("GridPlanner: start " + describe(start) +
                            " is outside the map or too close to an obstacle for the robot");
  }
  return *cell;
}

std::optional<PlannedLeg> GridPlanner::planToNearest(WorldPoint start,
                                                     std::span<const CellIndex> goals) const {
  const auto path = search().search(startCell(start), goals);
  if (!path) {
    return std::nullopt;
  }
  PlannedLeg leg;
  leg.goal = path->goal;
  const std::vector<CellIndex> kept = shortcutPath(clearance_, path->cells, config_.comfortClearance);
  leg.waypoints.push_back(start);
  for (std::size_t i = 1; i < kept.size(); ++i) {
    leg.waypoints.push_back(grid().center(kept[i]));
  }
  if (kept.size() == 1) {
    leg.waypoints.push_back(grid().center(kept.front()));
  }
  return leg;
}

std::vector<WorldPoint> GridPlanner::plan(WorldPoint start, WorldPoint goal) const {
  const CellIndex from = startCell(start);
  const auto goalCell = grid().cellOf(goal);
  if (!goalCell || !traversable(*goalCell)) {
    throw GoalBlockedError("GridPlanner: goal " + describe(goal) +
                           " is outside the map or too close to an obstacle for the robot");
  }
  auto leg = planToNearest(grid().center(from), std::span(&*goalCell, 1));
  if (!leg) {
    throw NoPathError("GridPlanner: no path from " + describe(start) + " to " + describe(goal) +
                      " for a robot of radius " + std::to_string(config_.robotRadius) + " m");
  }
  leg->waypoints.front() = start;
  leg->waypoints.back() = goal;
  return std::move(leg->waypoints);
}

std::vector<bool> GridPlanner::reachableFrom(WorldPoint start) const {
  return search().connected(startCell(start));
}

}  // namespace rgnav
