// The PathPlanning module's parameters from YAML (config/modules/pathplanning.yaml): every key of
// RoutePlannerConfig (RoutePlanner.h) and of its region planner's FramedQuadtreePlannerConfig
// required, no other key allowed, validated as the route planner validates them. Errors are
// ConfigErrors naming the file, the key path and the line (DescribedConfig.h).
#pragma once

#include <string>

#include "core/nav/planning/RoutePlanner.h"

namespace rgnav {

template <class V>
void describe(V& v, FramedQuadtreePlannerConfig& c) {
  v.field("wall_cost_distance_m", c.wallCostDistanceM);
  v.field("wall_cost_weight", c.wallCostWeight);
}

template <class V>
void describe(V& v, RoutePlannerConfig& c) {
  v.field("robot_radius_m", c.robotRadiusM);
  v.field("grid_resolution_m", c.gridResolutionM);
  v.field("start_snap_m", c.startSnapM);
  v.field("crossing_snap_m", c.crossingSnapM);
  v.field("overlap_sample_m", c.overlapSampleM);
  v.field("overlap_min_area_m2", c.overlapMinAreaM2);
  v.field("target_min_spacing_m", c.targetMinSpacingM);
  v.field("target_max_spacing_m", c.targetMaxSpacingM);
  v.section("region", c.region);
}

// `path` names the text in errors.
RoutePlannerConfig parseRoutePlannerConfig(const std::string& yamlText, const std::string& path);
// FileError if the file cannot be read.
RoutePlannerConfig loadRoutePlannerConfig(const std::string& file);

}  // namespace rgnav
