// Beam-to-point conversion and PCA normals along the scan.
#include "core/slam/ScanPoints.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace rgnav {

std::vector<Eigen::Vector2f> scanToPoints(const LaserScan& scan, const ScanPointsConfig& config) {
  std::vector<Eigen::Vector2f> points;
  points.reserve(scan.ranges.size());
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double r = scan.ranges[i];
    if (!std::isfinite(r) || r < config.minRange || r > config.maxRange) continue;
    const double a = scan.startAngle + static_cast<double>(i) * scan.angleIncrement;
    points.emplace_back(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)));
  }
  return points;
}

std::vector<Eigen::Vector2f> estimateNormals(std::span<const Eigen::Vector2f> points, const ScanPointsConfig& config) {
  std::vector<Eigen::Vector2f> normals(points.size(), Eigen::Vector2f::Zero());
  const double radius2 = config.normalRadius * config.normalRadius;
  const std::size_t half = config.normalHalfWindow;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d centre = points[i].cast<double>();
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    Eigen::Matrix2d outer = Eigen::Matrix2d::Zero();
    int count = 0;
    const std::size_t begin = i >= half ? i - half : 0;
    const std::size_t end = std::min(points.size(), i + half + 1);
    for (std::size_t j = begin; j < end; ++j) {
      const Eigen::Vector2d p = points[j].cast<double>();
      if ((p - centre).squaredNorm() > radius2) continue;
      sum += p;
      outer += p * p.transpose();
      ++count;
    }
    if (count < 3) continue;
    const Eigen::Vector2d mean = sum / count;
    const Eigen::Matrix2d covariance = outer / count - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(covariance);
    const Eigen::Vector2d values = eigen.eigenvalues();  // ascending
    if (values(1) <= 0.0 || values(0) > config.maxPlanarity * values(1)) continue;
    Eigen::Vector2d normal = eigen.eigenvectors().col(0);
    if (normal.dot(centre) > 0.0) normal = -normal;  // face the sensor
    normals[i] = normal.cast<float>();
  }
  return normals;
}

}  // namespace rgnav
