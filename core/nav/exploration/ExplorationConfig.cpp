// Range checks of the exploration parameters (ExplorationConfig.h).
#include "core/nav/exploration/ExplorationConfig.h"

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"

namespace rgnav {

void validate(const ExplorationConfig& config) {
  requirePositive(config.grid.resolutionM, "exploration grid resolution_m");
  requireNonNegative(config.grid.wallClearanceM, "exploration grid wall_clearance_m");
  if (config.frontier.minCells == 0) throw ConfigError("exploration frontier min_cells must be at least 1");
  requirePositive(config.frontier.usefulRangeM, "exploration frontier useful_range_m");
  requireNonNegative(config.frontier.viewpointBackoffM, "exploration frontier viewpoint_backoff_m");
  if (config.frontier.viewpointBackoffM >= config.frontier.usefulRangeM)
    throw ConfigError("exploration frontier viewpoint_backoff_m must be less than useful_range_m");
  requireNonNegative(config.robotRadiusM, "exploration robot_radius_m");
  if (config.maxGoalFailures == 0) throw ConfigError("exploration max_goal_failures must be at least 1");
  requirePositive(config.regoalPeriodS, "exploration regoal_period_s");
}

}  // namespace rgnav
