// Validation of the Collision Avoidance's parameters (see CollisionAvoidanceConfig.h).
#include "core/nav/avoidance/CollisionAvoidanceConfig.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"

namespace rgnav {

namespace {

void positive(double value, const std::string& name) { requirePositive(value, "collision avoidance: " + name); }

void nonNegative(double value, const std::string& name) { requireNonNegative(value, "collision avoidance: " + name); }

}  // namespace

void validate(const CandidateConfig& c) {
  positive(c.horizonM, "candidates.horizon_m");
  positive(c.turnMaxCurvaturePerM, "candidates.turn_max_curvature_per_m");
  positive(c.turnSharpnessPerM2, "candidates.turn_sharpness_per_m2");
  positive(c.manoeuvreSharpnessPerM2, "candidates.manoeuvre_sharpness_per_m2");
  if (!(c.turnMaxSharpnessPerM2 >= std::max(c.turnSharpnessPerM2, c.manoeuvreSharpnessPerM2)) ||
      !std::isfinite(c.turnMaxSharpnessPerM2))
    throw ConfigError("collision avoidance: candidates.turn_max_sharpness_per_m2 must not be below the sharpnesses");
  positive(c.lateralStepM, "candidates.lateral_step_m");
  if (!(c.fanMaxDeflectionRad >= 0.0) || !(c.fanMaxDeflectionRad < M_PI))
    throw ConfigError("collision avoidance: candidates.fan_max_deflection_deg must lie in [0, 180)");
  positive(c.fanLengthM, "candidates.fan_length_m");
  positive(c.pivotStepRad, "candidates.pivot_step_deg");
}

void validate(const GoalSeekingConfig& c) {
  positive(c.replanPeriodS, "goal_seeking.replan_period_s");
  nonNegative(c.inflationMarginM, "goal_seeking.inflation_margin_m");
  positive(c.comfortClearanceM, "goal_seeking.comfort_clearance_m");
  nonNegative(c.clearanceWeight, "goal_seeking.clearance_weight");
  positive(c.targetMinSpacingM, "goal_seeking.target_min_spacing_m");
  if (!(c.targetMaxSpacingM >= c.targetMinSpacingM))
    throw ConfigError("collision avoidance: goal_seeking.target_max_spacing_m must not be below the minimum");
}

void validate(const CollisionAvoidanceConfig& c) {
  validate(c.obstacleMap);
  validate(c.candidates);
  validate(c.goalSeeking);
  nonNegative(c.safetyMarginM, "safety_margin_m");
  nonNegative(c.escapeMarginM, "escape_margin_m");
  positive(c.sampleStepM, "sample_step_m");
  nonNegative(c.comfortClearanceM, "comfort_clearance_m");
  nonNegative(c.clearanceWeightSPerM, "clearance_weight_s_per_m");
  nonNegative(c.progressWeightSPerM, "progress_weight_s_per_m");
  nonNegative(c.planningLatencyS, "planning_latency_s");
  nonNegative(c.oncomingSpeedMps, "oncoming_speed_mps");
  positive(c.replanPeriodS, "replan_period_s");
  nonNegative(c.refreshDistanceM, "refresh_distance_m");
  positive(c.targetPassedM, "target_passed_m");
  positive(c.goalToleranceM, "goal_tolerance_m");
  positive(c.blockedWaitS, "blocked_wait_s");
}

}  // namespace rgnav
