// Depth singularities of a point scan; see DepthSingularities.h.
#include "core/gateways/vlm/DepthSingularities.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

bool isMeasurement(const LaserScan& scan, double r) {
  return std::isfinite(r) && r > 0.0 && (scan.maxRange <= 0.0 || r < scan.maxRange);
}

// Whether neighbour range n lies farther than d by more than minJump (no return: infinitely far).
bool jumpsAway(double d, double n, double minJump) { return !std::isnan(n) && n > d && n - d > minJump; }

Eigen::Vector2d beamPoint(const LaserScan& scan, std::size_t beam, double range) {
  const double bearing = scan.startAngle + double(beam) * scan.angleIncrement;
  return {range * std::cos(bearing), range * std::sin(bearing)};
}

}  // namespace

std::vector<Eigen::Vector2d> depthSingularities(const LaserScan& scan, double minJumpM) {
  if (!(minJumpM > 0.0)) throw InvalidArgumentError("depth singularities: the minimum jump must be positive");
  std::vector<Eigen::Vector2d> result;
  const std::size_t n = scan.ranges.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double d = scan.ranges[i];
    if (!isMeasurement(scan, d)) continue;
    const bool before = i > 0 && jumpsAway(d, scan.ranges[i - 1], minJumpM);
    const bool after = i + 1 < n && jumpsAway(d, scan.ranges[i + 1], minJumpM);
    if (before || after) result.push_back(beamPoint(scan, i, d));
  }
  return result;
}

}  // namespace rgnav
