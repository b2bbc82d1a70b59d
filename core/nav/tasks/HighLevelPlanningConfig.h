// HighLevelPlanningConfig: the parameters of the High-Level Planning module
// (config/modules/highlevelplanning.yaml, HighLevelPlanningConfigYaml.h): how often it looks after
// its tasks and the naming dialog, exploration's parameters (ExplorationConfig.h), and the route
// planner it measures exploration's driving distances with (RoutePlanner.h; the drives themselves
// are planned by the PathPlanning module). The exploration strategy is the module's --strategy.
#pragma once

#include "core/nav/exploration/ExplorationConfig.h"
#include "core/nav/planning/RoutePlanner.h"

namespace rgnav {

struct HighLevelPlanningConfig {
  double pollPeriodS = 0.2;  // the task loop: drive status, kernel summary, explorer
  ExplorationConfig exploration;
  RoutePlannerConfig routePlanner;
};

// Throws ConfigError naming the first value out of range.
void validate(const HighLevelPlanningConfig& config);

}  // namespace rgnav
