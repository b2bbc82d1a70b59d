// Mean and population standard deviation of the per-relation errors.
#include "core/slam/eval/RelativePoseMetric.h"

#include <algorithm>
#include <cmath>

namespace rgnav {

namespace {
void meanAndStd(double sum, double sumSquares, std::size_t n, double& mean, double& stdDev) {
  mean = sum / static_cast<double>(n);
  stdDev = std::sqrt(std::max(0.0, sumSquares / static_cast<double>(n) - mean * mean));
}
}  // namespace

RelativePoseError relativePoseError(std::span<const ScanRelation> relations, const std::function<Pose2D(DataId)>& pose) {
  RelativePoseError result;
  if (relations.empty()) return result;
  double t = 0, t2 = 0, r = 0, r2 = 0;
  for (const ScanRelation& relation : relations) {
    const Pose2D estimated = between(pose(relation.first), pose(relation.second));
    const Pose2D error = between(relation.relative, estimated);
    const double translation = std::hypot(error.x, error.y);
    const double rotation = std::abs(normalizeAngle(error.theta));
    t += translation;
    t2 += translation * translation;
    r += rotation;
    r2 += rotation * rotation;
  }
  result.relations = relations.size();
  meanAndStd(t, t2, relations.size(), result.translationMean, result.translationStd);
  meanAndStd(r, r2, relations.size(), result.rotationMean, result.rotationStd);
  return result;
}

}  // namespace rgnav
