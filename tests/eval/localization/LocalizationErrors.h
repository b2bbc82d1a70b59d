// LocalizationErrors: how far a localizer's estimates lie from the corrected poses, for the
// localization evaluation (issue 28): per scan the translation and rotation error of the estimate
// (the mean of the heaviest particle cluster) and of the best particle, and their summary: mean
// and 95th percentile of the translation error, mean rotation error, and the scans "lost" (a
// translation error over lostM, 1 m in the issue).
#pragma once

#include <cstddef>
#include <span>

#include "core/common/Pose2D.h"

namespace rgnav {

struct PoseError {
  double translationM = 0.0;
  double rotationRad = 0.0;  // absolute, in [0, pi]
};

PoseError poseError(const Pose2D& estimate, const Pose2D& truth);

struct ErrorSummary {
  std::size_t scans = 0;
  double translationMeanM = 0.0;
  double translationP95M = 0.0;  // nearest-rank 95th percentile
  double rotationMeanDeg = 0.0;
  std::size_t lost = 0;
};

// Zeros for no errors.
ErrorSummary summarize(std::span<const PoseError> errors, double lostM);

}  // namespace rgnav
