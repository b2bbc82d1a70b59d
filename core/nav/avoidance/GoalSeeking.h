// GoalSeeking: target poses toward a goal where the robot has no map (the BARN benchmark, later
// exploration): the clearance-weighted grid planner (core/nav/grid GridPlanner) on the obstacle
// cells sensed so far, space never seen counting as free, free space inflated by the footprint's
// inscribed radius plus a margin (the Collision Avoidance's swept check then tests the exact
// footprint), the path cut into targets 0.5-2 m apart (TargetSpacing, thesis 5.5.3). The caller
// replans every replanPeriodS and whenever the Collision Avoidance reports it is blocked. Stands in
// for thesis 5.4's RG-map path planning where no RG map exists yet.
#pragma once

#include <optional>
#include <vector>

#include "core/nav/avoidance/CollisionAvoidanceConfig.h"
#include "core/nav/grid/Footprint.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

class GoalSeeking {
 public:
  // Throws ConfigError for a bad configuration or footprint.
  GoalSeeking(const GoalSeekingConfig& config, const Footprint& footprint);

  // Targets from `from` to `goal` over `obstacles` (Occupied cells; anything else free); a goal
  // outside the grid is approached through the nearest point inside it. nullopt when no path
  // exists even with the bare inscribed radius (the robot is walled in as far as it has seen).
  // `extraMarginM` widens the inflation (after the Collision Avoidance found a path too narrow).
  std::optional<std::vector<Pose2D>> plan(const OccupancyGrid& obstacles, const Pose2D& from, WorldPoint goal,
                                          double extraMarginM = 0.0) const;

 private:
  std::optional<std::vector<WorldPoint>> path(const OccupancyGrid& grid, WorldPoint from, WorldPoint goal,
                                              double radius) const;

  GoalSeekingConfig config_;
  Footprint footprint_;
};

}  // namespace rgnav
