// The LowLevelDrive module's parameters from YAML (config/modules/lowleveldrive.yaml): every key
// of LowLevelDriveConfig (LowLevelDrive.h) with its MotionLimits and PostureGains required, no
// other key allowed, validated as the Low-Level Drive validates them. Errors are ConfigErrors
// naming the file, the key path and the line (DescribedConfig.h).
#pragma once

#include <string>

#include "core/nav/motion/LowLevelDrive.h"

namespace rgnav {

template <class V>
void describe(V& v, MotionLimits& c) {
  v.field("max_velocity_mps", c.maxVelocity);
  v.field("max_acceleration_mps2", c.maxAcceleration);
  v.field("max_deceleration_mps2", c.maxDeceleration);
  v.field("max_rotational_velocity_radps", c.maxRotationalVelocity);
  v.field("max_rotational_acceleration_radps2", c.maxRotationalAcceleration);
  v.field("max_lateral_acceleration_mps2", c.maxLateralAcceleration);
}

template <class V>
void describe(V& v, PostureGains& c) {
  v.field("kx_per_s", c.kx);
  v.field("ky_per_m2", c.ky);
  v.field("ktheta_per_m", c.ktheta);
}

template <class V>
void describe(V& v, LowLevelDriveConfig& c) {
  v.field("period_s", c.periodSeconds);
  v.field("odometry_timeout_s", c.odometryTimeoutSeconds);
  v.field("command_delay_ticks", c.commandDelayTicks);
  v.field("reference_margin", c.referenceMargin);
  v.section("limits", c.limits);
  v.section("gains", c.gains);
}

// `path` names the text in errors.
LowLevelDriveConfig parseLowLevelDriveConfig(const std::string& yamlText, const std::string& path);
// FileError if the file cannot be read.
LowLevelDriveConfig loadLowLevelDriveConfig(const std::string& file);

}  // namespace rgnav
