// GridPlanner: paths for a round robot on an OccupancyGrid. Free space is inflated by the robot
// radius (a cell is traversable if a disk of that radius at its centre overlaps no blocked
// cell: clearance >= radius + half a cell diagonal); A* with a clearance cost (GridSearch) keeps
// paths away from walls; line-of-sight shortcutting (PathShortcut) reduces the cell path to
// waypoints that keep the comfort clearance wherever the cell path had it. Failures are typed
// (PlanningErrors.h).
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/nav/grid/ClearanceMap.h"
#include "core/nav/grid/GridSearch.h"

namespace rgnav {

struct GridPlannerConfig {
  double robotRadius = 0.25;        // m; 0.25 for a 0.5 m wide robot
  double comfortClearance = 0.8;    // m; paths closer to a wall than this pay extra
  double clearanceWeight = 4.0;     // extra cost per metre at the smallest clearance
};

// Throws ConfigError for non-positive radius/clearances or a negative weight.
void validate(const GridPlannerConfig& config);

struct PlannedLeg {
  std::size_t goal = 0;              // index into the goals given
  std::vector<WorldPoint> waypoints; // the start point first, the goal cell's centre last
};

class GridPlanner {
 public:
  // Computes the clearance map. Keeps a reference to `grid`, which must outlive the planner.
  // Throws ConfigError for a bad configuration.
  explicit GridPlanner(const OccupancyGrid& grid, const GridPlannerConfig& config = {});
  GridPlanner(OccupancyGrid&&, const GridPlannerConfig& = {}) = delete;

  const OccupancyGrid& grid() const { return clearance_.grid(); }
  const ClearanceMap& clearance() const { return clearance_; }
  bool traversable(CellIndex c) const { return search().traversable(c); }

  // Waypoints from `start` to `goal` (both exact). Throws StartBlockedError, GoalBlockedError or
  // NoPathError.
  std::vector<WorldPoint> plan(WorldPoint start, WorldPoint goal) const;

  // The path to whichever of `goals` is cheapest to reach; nullopt if none is connected to
  // `start`. Throws StartBlockedError.
  std::optional<PlannedLeg> planToNearest(WorldPoint start, std::span<const CellIndex> goals) const;

  // Traversable cells connected to `start` (row-major). Throws StartBlockedError.
  std::vector<bool> reachableFrom(WorldPoint start) const;

 private:
  GridSearch search() const;
  CellIndex startCell(WorldPoint start) const;

  GridPlannerConfig config_;
  ClearanceMap clearance_;
};

}  // namespace rgnav
