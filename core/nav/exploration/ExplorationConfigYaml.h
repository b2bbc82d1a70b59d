// Exploration parameters from YAML: every key of ExplorationConfig (ExplorationConfig.h) with its
// grid and frontier sections required, no other key allowed, validated as the explorer validates
// them (validate(ExplorationConfig)). The High-Level Planning module's file holds them as its
// `exploration:` section: list it with v.section("exploration", c.exploration) in the module's own
// describe(), or read the section alone with explorationConfigFromYaml. Errors are ConfigErrors
// naming the file, the key path and the line (DescribedConfig.h).
#pragma once

#include <string>

#include "core/config/ConfigNode.h"
#include "core/nav/exploration/ExplorationConfig.h"

namespace rgnav {

template <class V>
void describe(V& v, ExplorationGridConfig& c) {
  v.field("resolution_m", c.resolutionM);
  v.field("wall_clearance_m", c.wallClearanceM);
}

template <class V>
void describe(V& v, FrontierConfig& c) {
  v.field("min_cells", c.minCells);
  v.field("useful_range_m", c.usefulRangeM);
  v.field("viewpoint_backoff_m", c.viewpointBackoffM);
}

template <class V>
void describe(V& v, ExplorationConfig& c) {
  v.section("grid", c.grid);
  v.section("frontier", c.frontier);
  v.field("robot_radius_m", c.robotRadiusM);
  v.field("max_goal_failures", c.maxGoalFailures);
  v.field("regoal_period_s", c.regoalPeriodS);
}

// A section of a larger file, e.g. node["exploration"] of the High-Level Planning module's.
ExplorationConfig explorationConfigFromYaml(const ConfigNode& section);
// A document that is the exploration configuration; `path` names the text in errors.
ExplorationConfig parseExplorationConfig(const std::string& yamlText, const std::string& path);
// FileError if the file cannot be read.
ExplorationConfig loadExplorationConfig(const std::string& file);

}  // namespace rgnav
