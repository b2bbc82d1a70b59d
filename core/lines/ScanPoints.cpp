// Conversion of scan ranges to points; see ScanPoints.h.
#include "core/lines/ScanPoints.h"

#include <cmath>

namespace rgnav {

Eigen::Vector2d transformPoint(const Pose2D& pose, const Eigen::Vector2d& p) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  return {pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y()};
}

std::vector<ScanPoint> scanPoints(const LaserScan& scan, const Pose2D& sensorPose) {
  std::vector<ScanPoint> points;
  points.reserve(scan.ranges.size());
  for (std::size_t beam = 0; beam < scan.ranges.size(); ++beam) {
    const double r = scan.ranges[beam];
    if (!std::isfinite(r) || r <= 0.0 || (scan.maxRange > 0.0 && r >= scan.maxRange)) continue;
    const double bearing = scan.startAngle + double(beam) * scan.angleIncrement;
    const Eigen::Vector2d local(r * std::cos(bearing), r * std::sin(bearing));
    points.push_back({transformPoint(sensorPose, local), r, beam});
  }
  return points;
}

}  // namespace rgnav
