// Validation of SlamConfig: positive sizes, finite positive distances, ordered ranges.
#include "core/slam/SlamConfig.h"

#include <cmath>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

void requirePositive(double value, const std::string& key) {
  if (!std::isfinite(value) || value <= 0.0) throw ConfigError("slam: " + key + " must be positive, got " + std::to_string(value));
}

void requireNonNegative(double value, const std::string& key) {
  if (!std::isfinite(value) || value < 0.0)
    throw ConfigError("slam: " + key + " must not be negative, got " + std::to_string(value));
}

void requireFraction(double value, const std::string& key) {
  if (!(value >= 0.0 && value <= 1.0)) throw ConfigError("slam: " + key + " must lie in [0, 1], got " + std::to_string(value));
}

void requireCount(std::size_t value, const std::string& key) {
  if (value == 0) throw ConfigError("slam: " + key + " must be at least 1");
}

void validateGrid(const GridConfig& grid, const std::string& prefix) {
  requirePositive(grid.resolution, prefix + ".resolution");
  requirePositive(grid.sigma, prefix + ".sigma");
  requirePositive(grid.nearestRadius, prefix + ".nearestRadius");
}

}  // namespace

void validate(const SlamConfig& c) {
  requireNonNegative(c.filter.minTranslation, "filter.minTranslation");
  requireNonNegative(c.filter.minRotation, "filter.minRotation");

  requireNonNegative(c.points.minRange, "points.minRange");
  requirePositive(c.points.maxRange, "points.maxRange");
  if (c.points.maxRange <= c.points.minRange) throw ConfigError("slam: points.maxRange must exceed points.minRange");
  requireCount(c.points.normalHalfWindow, "points.normalHalfWindow");
  requirePositive(c.points.normalRadius, "points.normalRadius");
  requireFraction(c.points.maxPlanarity, "points.maxPlanarity");
  requireCount(c.points.minPoints, "points.minPoints");

  requireCount(c.icp.maxIterations, "icp.maxIterations");
  requirePositive(c.icp.maxCorrespondence, "icp.maxCorrespondence");
  requirePositive(c.icp.huberDelta, "icp.huberDelta");
  requirePositive(c.icp.inlierResidual, "icp.inlierResidual");
  requirePositive(c.icp.convergedStep, "icp.convergedStep");
  requirePositive(c.icp.pointSigma, "icp.pointSigma");
  requirePositive(c.icp.effectivePoints, "icp.effectivePoints");

  requireCount(c.local.windowKeyframes, "local.windowKeyframes");
  requireNonNegative(c.local.searchTranslation, "local.searchTranslation");
  requireNonNegative(c.local.searchRotation, "local.searchRotation");
  requireFraction(c.local.minScore, "local.minScore");
  requireFraction(c.local.minInlierFraction, "local.minInlierFraction");
  validateGrid(c.local.grid, "local.grid");
  requireNonNegative(c.local.odometry.translationPerMetre, "local.odometry.translationPerMetre");
  requireNonNegative(c.local.odometry.rotationPerRadian, "local.odometry.rotationPerRadian");
  requireNonNegative(c.local.odometry.rotationPerMetre, "local.odometry.rotationPerMetre");
  requirePositive(c.local.odometry.minTranslation, "local.odometry.minTranslation");
  requirePositive(c.local.odometry.minRotation, "local.odometry.minRotation");

  requireCount(c.loop.submapKeyframes, "loop.submapKeyframes");
  if (c.loop.excludeRecentKeyframes < c.local.windowKeyframes)
    throw ConfigError("slam: loop.excludeRecentKeyframes must be at least local.windowKeyframes");
  requireNonNegative(c.loop.candidateRadius, "loop.candidateRadius");
  requireNonNegative(c.loop.windowTranslation, "loop.windowTranslation");
  requireNonNegative(c.loop.windowTranslationPerMetre, "loop.windowTranslationPerMetre");
  requireNonNegative(c.loop.maxWindowTranslation, "loop.maxWindowTranslation");
  requireNonNegative(c.loop.windowRotation, "loop.windowRotation");
  requireNonNegative(c.loop.windowRotationPerMetre, "loop.windowRotationPerMetre");
  requireNonNegative(c.loop.maxWindowRotation, "loop.maxWindowRotation");
  if (c.loop.maxWindowRotation > M_PI) throw ConfigError("slam: loop.maxWindowRotation must not exceed pi");
  requireCount(c.loop.maxCandidates, "loop.maxCandidates");
  requireFraction(c.loop.minScore, "loop.minScore");
  requireFraction(c.loop.minInlierFraction, "loop.minInlierFraction");
  requireFraction(c.loop.undetermined.maxInformationRatio, "loop.undetermined.maxInformationRatio");
  requirePositive(c.loop.undetermined.shift, "loop.undetermined.shift");
  requireFraction(c.loop.undetermined.minScoreDrop, "loop.undetermined.minScoreDrop");
  requireCount(c.loop.cachedSubmaps, "loop.cachedSubmaps");
  validateGrid(c.loop.grid, "loop.grid");

  requirePositive(c.graph.loopLossScale, "graph.loopLossScale");
  requireCount(c.graph.maxIterations, "graph.maxIterations");
  requirePositive(c.graph.functionTolerance, "graph.functionTolerance");
  requireCount(c.graph.keyframesBetweenOptimizations, "graph.keyframesBetweenOptimizations");
  requireNonNegative(c.graph.immediateCorrection, "graph.immediateCorrection");
  requireCount(c.graph.keptRevisions, "graph.keptRevisions");
}

}  // namespace rgnav
