// Narrow-passage thresholds: derived width and validation (see PassageConfig.h).
#include "core/gateways/passages/PassageConfig.h"

#include <string>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

void requirePositive(double value, const char* name) {
  if (!std::isfinite(value) || value <= 0.0)
    throw ConfigError(std::string("narrow passages: ") + name + " must be positive and finite, got " +
                      std::to_string(value));
}

void requireAngle(double value, const char* name) {
  requirePositive(value, name);
  if (value > M_PI) throw ConfigError(std::string("narrow passages: ") + name + " must not exceed pi");
}

}  // namespace

double minPassageWidthM(const NarrowPassageConfig& config) {
  return 2.0 * (config.robotRadiusM + config.safetyDistanceM);
}

void validate(const NarrowPassageConfig& config) {
  requirePositive(config.robotRadiusM, "robotRadiusM");
  if (!std::isfinite(config.safetyDistanceM) || config.safetyDistanceM < 0.0)
    throw ConfigError("narrow passages: safetyDistanceM must be finite and not negative");
  requirePositive(config.maxDoorWidthM, "maxDoorWidthM");
  if (config.maxDoorWidthM <= minPassageWidthM(config))
    throw ConfigError("narrow passages: maxDoorWidthM must exceed 2 (robotRadiusM + safetyDistanceM) = " +
                      std::to_string(minPassageWidthM(config)));
  requirePositive(config.maxDistanceM, "maxDistanceM");
  requireAngle(config.minApertureRad, "minApertureRad");
  requireAngle(config.halfRangeRad, "halfRangeRad");
  requireAngle(config.viewingStepRad, "viewingStepRad");
  requirePositive(config.minDepthBehindM, "minDepthBehindM");
  if (config.minBeamsBehind == 0) throw ConfigError("narrow passages: minBeamsBehind must be at least 1");
  if (!std::isfinite(config.minJambLengthM) || config.minJambLengthM < 0.0)
    throw ConfigError("narrow passages: minJambLengthM must be finite and not negative");
  requirePositive(config.minWallEndLengthM, "minWallEndLengthM");
  requirePositive(config.wallEndToleranceM, "wallEndToleranceM");
  if (!(config.surfaceBreaks.lambdaRad > 0.0 && config.surfaceBreaks.lambdaRad < M_PI / 2) ||
      !(config.surfaceBreaks.rangeSigmaM >= 0.0))
    throw ConfigError("narrow passages: surfaceBreaks needs lambdaRad in (0, pi/2) and rangeSigmaM >= 0");
}

}  // namespace rgnav
