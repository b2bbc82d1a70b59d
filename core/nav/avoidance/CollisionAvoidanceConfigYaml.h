// The Collision Avoidance's parameters from YAML (config/modules/collisionavoidance.yaml): every
// key of CollisionAvoidanceConfig and its sections required, no other key allowed, units in the
// key names, validated as the Collision Avoidance validates them. Errors are ConfigErrors naming
// the file, the key path and the line (DescribedConfig.h).
#pragma once

#include <string>

#include "core/nav/avoidance/CollisionAvoidanceConfig.h"

namespace rgnav {

template <class V>
void describe(V& v, LaserObstacleMapConfig& c) {
  v.field("resolution_m", c.resolutionM);
  v.field("size_m", c.sizeM);
  v.field("recenter_margin_m", c.recenterMarginM);
  v.field("laser_forward_offset_m", c.laserForwardOffsetM);
  v.field("max_clear_range_m", c.maxClearRangeM);
  v.field("hit_log_odds", c.hitLogOdds);
  v.field("miss_log_odds", c.missLogOdds);
  v.field("clamp_log_odds", c.clampLogOdds);
  v.field("occupied_log_odds", c.occupiedLogOdds);
  v.field("free_log_odds", c.freeLogOdds);
}

template <class V>
void describe(V& v, CandidateConfig& c) {
  v.field("horizon_m", c.horizonM);
  v.field("lateral_step_m", c.lateralStepM);
  v.field("lateral_count", c.lateralCount);
  v.field("arc_max_curvature_per_m", c.arcMaxCurvaturePerM);
  v.field("arc_count", c.arcCount);
  v.field("arc_length_m", c.arcLengthM);
}

template <class V>
void describe(V& v, GoalSeekingConfig& c) {
  v.field("replan_period_s", c.replanPeriodS);
  v.field("inflation_margin_m", c.inflationMarginM);
  v.field("comfort_clearance_m", c.comfortClearanceM);
  v.field("clearance_weight", c.clearanceWeight);
  v.field("target_min_spacing_m", c.targetMinSpacingM);
  v.field("target_max_spacing_m", c.targetMaxSpacingM);
}

template <class V>
void describe(V& v, CollisionAvoidanceConfig& c) {
  v.section("obstacle_map", c.obstacleMap);
  v.section("candidates", c.candidates);
  v.section("goal_seeking", c.goalSeeking);
  v.field("safety_margin_m", c.safetyMarginM);
  v.field("sample_step_m", c.sampleStepM);
  v.field("comfort_clearance_m", c.comfortClearanceM);
  v.field("clearance_weight_s_per_m", c.clearanceWeightSPerM);
  v.field("progress_weight_s_per_m", c.progressWeightSPerM);
  v.field("planning_latency_s", c.planningLatencyS);
  v.field("replan_period_s", c.replanPeriodS);
  v.field("target_passed_m", c.targetPassedM);
  v.field("goal_tolerance_m", c.goalToleranceM);
  v.field("blocked_wait_s", c.blockedWaitS);
}

// `path` names the text in errors.
CollisionAvoidanceConfig parseCollisionAvoidanceConfig(const std::string& yamlText, const std::string& path);
// FileError if the file cannot be read.
CollisionAvoidanceConfig loadCollisionAvoidanceConfig(const std::string& file);

}  // namespace rgnav
