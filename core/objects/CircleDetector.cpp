// Circle detection on clustered points; see CircleDetector.h.
#include "core/objects/CircleDetector.h"

#include <algorithm>

#include "core/common/Errors.h"
#include "core/objects/CircleFit.h"
#include "core/objects/PointClustering.h"

namespace rgnav {
namespace {

// 2 pi minus the largest angular gap between the points seen from the centre.
double coveredArc(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& center) {
  std::vector<double> angles;
  for (const auto& p : points) angles.push_back(std::atan2(p.y() - center.y(), p.x() - center.x()));
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2.0 * M_PI - angles.back();
  for (std::size_t i = 1; i < angles.size(); ++i) gap = std::max(gap, angles[i] - angles[i - 1]);
  return 2.0 * M_PI - gap;
}

}  // namespace

CircleDetector::CircleDetector(const CircleDetectorParams& params) : params_(params) {
  if (!(params.clusterGapM > 0.0) || params.minPoints < 3 || !(params.minRadiusM >= 0.0) ||
      !(params.maxRadiusM > params.minRadiusM) || !(params.maxResidualM > 0.0) ||
      !(params.minArcRad >= 0.0 && params.minArcRad <= 2.0 * M_PI))
    throw InvalidArgumentError(
        "circle detector: need clusterGapM > 0, minPoints >= 3, 0 <= minRadius < maxRadius, maxResidual > 0, "
        "minArc in [0, 2 pi]");
}

std::vector<Circle2D> CircleDetector::detect(const std::vector<Eigen::Vector2d>& points) const {
  std::vector<Circle2D> circles;
  std::vector<Eigen::Vector2d> cluster;
  for (const auto& members : clusterPoints(points, params_.clusterGapM)) {
    if (members.size() < params_.minPoints) continue;
    cluster.clear();
    for (const std::size_t i : members) cluster.push_back(points[i]);
    const auto fit = fitCircle(cluster);
    if (!fit || fit->radiusM < params_.minRadiusM || fit->radiusM > params_.maxRadiusM ||
        fit->rmsResidualM > params_.maxResidualM)
      continue;
    const double arc = coveredArc(cluster, fit->center);
    if (arc < params_.minArcRad) continue;
    const double confidence = std::min(1.0, arc / M_PI) * (1.0 - fit->rmsResidualM / params_.maxResidualM);
    circles.push_back({fit->center, fit->radiusM, fit->rmsResidualM, arc, confidence, cluster.size()});
  }
  std::stable_sort(circles.begin(), circles.end(),
                   [](const Circle2D& a, const Circle2D& b) { return a.confidence > b.confidence; });
  return circles;
}

}  // namespace rgnav
