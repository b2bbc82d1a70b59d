// The High-Level Planning module's parameters from YAML (config/modules/highlevelplanning.yaml):
// every key of HighLevelPlanningConfig (HighLevelPlanningConfig.h), of its ExplorationConfig
// (ExplorationConfigYaml.h) and of its RoutePlannerConfig (RoutePlannerConfigYaml.h) required, no
// other key allowed, validated as the module validates them. Errors are ConfigErrors naming the
// file, the key path and the line (DescribedConfig.h).
#pragma once

#include <string>

#include "core/nav/exploration/ExplorationConfigYaml.h"
#include "core/nav/planning/RoutePlannerConfigYaml.h"
#include "core/nav/tasks/HighLevelPlanningConfig.h"

namespace rgnav {

template <class V>
void describe(V& v, HighLevelPlanningConfig& c) {
  v.field("poll_period_s", c.pollPeriodS);
  v.section("exploration", c.exploration);
  v.section("route_planner", c.routePlanner);
}

// `path` names the text in errors.
HighLevelPlanningConfig parseHighLevelPlanningConfig(const std::string& yamlText, const std::string& path);
// FileError if the file cannot be read.
HighLevelPlanningConfig loadHighLevelPlanningConfig(const std::string& file);

}  // namespace rgnav
