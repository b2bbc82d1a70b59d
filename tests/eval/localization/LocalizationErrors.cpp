// Pose errors and their summary; see LocalizationErrors.h.
#include "tests/eval/localization/LocalizationErrors.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rgnav {

PoseError poseError(const Pose2D& estimate, const Pose2D& truth) {
  return {std::hypot(estimate.x - truth.x, estimate.y - truth.y), std::abs(normalizeAngle(estimate.theta - truth.theta))};
}

ErrorSummary summarize(std::span<const PoseError> errors, double lostM) {
  ErrorSummary summary;
  summary.scans = errors.size();
  if (errors.empty()) return summary;
  std::vector<double> translations;
  double rotationSum = 0.0;
  for (const PoseError& e : errors) {
    translations.push_back(e.translationM);
    summary.translationMeanM += e.translationM;
    rotationSum += e.rotationRad;
    summary.lost += e.translationM > lostM;
  }
  const double n = static_cast<double>(errors.size());
  summary.translationMeanM /= n;
  summary.rotationMeanDeg = rotationSum / n * 180.0 / M_PI;
  const auto rank = static_cast<std::size_t>(std::ceil(0.95 * n)) - 1;
  std::nth_element(translations.begin(), translations.begin() + static_cast<std::ptrdiff_t>(rank), translations.end());
  summary.translationP95M = translations[rank];
  return summary;
}

}  // namespace rgnav
