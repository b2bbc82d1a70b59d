// Ray-cast synthetic scans; see SyntheticScan.h.
#include "core/lines/testing/SyntheticScan.h"

#include <limits>
#include <random>

#include "core/lines/ScanPoints.h"

namespace rgnav::testing {

LaserScan syntheticScan(const std::vector<Wall>& walls, const Pose2D& sensorPose, const ScanSpec& spec) {
  LaserScan scan;
  scan.odometry = scan.sensorPose = sensorPose;
  scan.startAngle = spec.startAngleRad;
  scan.angleIncrement = spec.incrementRad;
  scan.maxRange = spec.maxRangeM;
  std::mt19937 random(spec.seed);
  std::normal_distribution<double> noise(0.0, spec.noiseSigmaM);
  const Eigen::Vector2d origin(sensorPose.x, sensorPose.y);
  for (std::size_t k = 0; k < spec.beams; ++k) {
    const double bearing = sensorPose.theta + spec.startAngleRad + double(k) * spec.incrementRad;
    const Eigen::Vector2d ray(std::cos(bearing), std::sin(bearing));
    double nearest = std::numeric_limits<double>::infinity();
    for (const Wall& w : walls) {
      // origin + t * ray = w.a + u * (w.b - w.a)
      const Eigen::Vector2d e = w.b - w.a, q = w.a - origin;
      const double den = ray.x() * e.y() - ray.y() * e.x();
      if (std::fabs(den) < 1e-12) continue;
      const double t = (q.x() * e.y() - q.y() * e.x()) / den;
      const double u = (q.x() * ray.y() - q.y() * ray.x()) / den;
      if (t > 0.0 && u >= 0.0 && u <= 1.0) nearest = std::min(nearest, t);
    }
    const double measured = nearest + (spec.noiseSigmaM > 0.0 ? noise(random) : 0.0);
    scan.ranges.push_back(nearest < spec.maxRangeM ? float(measured) : LaserScan::kNoReturn);
  }
  return scan;
}

std::vector<Wall> boxWalls(const Eigen::Vector2d& center, double thetaRad, double lengthM, double widthM) {
  const Pose2D pose{center.x(), center.y(), thetaRad};
  const double hx = lengthM / 2, hy = widthM / 2;
  const std::vector<Eigen::Vector2d> c{transformPoint(pose, {-hx, -hy}), transformPoint(pose, {hx, -hy}),
                                       transformPoint(pose, {hx, hy}), transformPoint(pose, {-hx, hy})};
  return {{c[0], c[1]}, {c[1], c[2]}, {c[2], c[3]}, {c[3], c[0]}};
}

}  // namespace rgnav::testing
