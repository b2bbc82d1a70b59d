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
  v.field("moving_memory_s", c.movingMemoryS);
}

template <class V>
void describe(V& v, CandidateConfig& c) {
  v.field("horizon_m", c.horizonM);
  v.field("turn_max_curvature_per_m", c.turnMaxCurvaturePerM);
  v.field("turn_sharpness_per_m2", c.turnSharpnessPerM2);
  v.field("manoeuvre_sharpness_per_m2", c.manoeuvreSharpnessPerM2);
  v.field("turn_max_sharpness_per_m2", c.turnMaxSharpnessPerM2);
  v.field("lateral_step_m", c.lateralStepM);
  v.field("lateral_count", c.lateralCount);
  v.degrees("fan_max_deflection_deg", c.fanMaxDeflectionRad);
  v.field("fan_count", c.fanCount);
  v.field("fan_length_m", c.fanLengthM);
  v.degrees("pivot_step_deg", c.pivotStepRad);
  v.field("pivot_count", c.pivotCount);
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
  v.field("escape_margin_m", c.escapeMarginM);
  v.field("oncoming_speed_mps", c.oncomingSpeedMps);
  v.field("sample_step_m", c.sampleStepM);
  v.field("comfort_clearance_m", c.comfortClearanceM);
  v.field("clearance_weight_s_per_m", c.clearanceWeightSPerM);
  v.field("progress_weight_s_per_m", c.progressWeightSPerM);
  v.field("planning_latency_s", c.planningLatencyS);
  v.field("replan_period_s", c.replanPeriodS);
  v.field("refresh_distance_m", c.refreshDistanceM);
  v.field("target_passed_m", c.targetPassedM);
  v.field("goal_tolerance_m", c.goalToleranceM);
  v.field("blocked_wait_s", c.blockedWaitS);
}

// `path` names the text in errors.
CollisionAvoidanceConfig parseCollisionAvoidanceConfig(const std::string& yamlText, const std::string& path);
// FileError if the file cannot be read.
CollisionAvoidanceConfig loadCollisionAvoidanceConfig(const std::string& file);

}  // namespace rgnav
