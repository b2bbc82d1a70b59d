// The truth in a SLAM map, fitted locally (see LocalTruth.h).
#include "tests/eval/globalloc/LocalTruth.h"

#include <cmath>

#include "core/lines/ScanPoints.h"

namespace rgnav {

bool poseWithin(const Pose2D& a, const Pose2D& b, double m, double rad) {
  return std::hypot(a.x - b.x, a.y - b.y) <= m && std::abs(normalizeAngle(a.theta - b.theta)) <= rad;
}

LocalTruth::LocalTruth(std::vector<ScanPlacement> scans, const Pose2D& mapToWorld, double sigmaM)
    : scans_(std::move(scans)), worldToMap_(inverse(mapToWorld)), sigmaM_(sigmaM) {}

Pose2D LocalTruth::toMap(const Pose2D& world) const {
  const Eigen::Vector2d p(world.x, world.y);
  double total = 0.0;
  Eigen::Vector2d worldMean = Eigen::Vector2d::Zero(), mapMean = Eigen::Vector2d::Zero();
  std::vector<std::pair<double, const ScanPlacement*>> near;
  for (const ScanPlacement& s : scans_) {
    const double d2 = (s.world - p).squaredNorm();
    if (d2 > 4.0 * sigmaM_ * sigmaM_) continue;
    const double w = std::exp(-d2 / (2.0 * sigmaM_ * sigmaM_));
    near.emplace_back(w, &s);
    total += w;
    worldMean += w * s.world;
    mapMean += w * s.map;
  }
  if (total <= 0.0) return compose(worldToMap_, world);
  worldMean /= total;
  mapMean /= total;
  double sxx = 0.0, sxy = 0.0, spread = 0.0;  // cross terms of the 2D Kabsch fit
  for (const auto& [w, s] : near) {
    const Eigen::Vector2d a = s->world - worldMean, b = s->map - mapMean;
    sxx += w * a.dot(b);
    sxy += w * (a.x() * b.y() - a.y() * b.x());
    spread += w * a.squaredNorm();
  }
  const double rotation = spread / total > 0.25 ? std::atan2(sxy, sxx) : worldToMap_.theta;
  const Pose2D rotate{0.0, 0.0, rotation};
  const Eigen::Vector2d at = mapMean + transformPoint(rotate, p - worldMean);
  return {at.x(), at.y(), normalizeAngle(world.theta + rotation)};
}

}  // namespace rgnav
