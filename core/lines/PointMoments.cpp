// Total-least-squares line fit from point moments; see PointMoments.h.
#include "core/lines/PointMoments.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

void PointMoments::add(const Eigen::Vector2d& point) {
  PointMoments single;
  single.count_ = 1.0;
  single.mean_ = point;
  add(single);
}

void PointMoments::add(const PointMoments& other) {
  if (other.count_ == 0.0) return;
  const double total = count_ + other.count_;
  const Eigen::Vector2d delta = other.mean_ - mean_;
  scatter_ += other.scatter_ + (count_ * other.count_ / total) * delta * delta.transpose();
  mean_ += (other.count_ / total) * delta;
  count_ = total;
}

LineFit PointMoments::fitLine() const {
  if (count_ < 2.0) throw InvalidArgumentError("line fit needs at least two points");
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen;
  eigen.computeDirect(scatter_);
  const double along = eigen.eigenvalues()(1);                  // spread along the line
  const double across = std::max(0.0, eigen.eigenvalues()(0));  // sum of squared residuals
  if (!(along > 0.0)) throw InvalidArgumentError("line fit on coincident points");

  LineFit fit;
  fit.centroid = mean_;
  fit.direction = eigen.eigenvectors().col(1).normalized();
  fit.normal = Eigen::Vector2d(-fit.direction.y(), fit.direction.x());
  fit.distanceM = fit.normal.dot(mean_);
  if (fit.distanceM < 0.0) {
    fit.normal = -fit.normal;
    fit.distanceM = -fit.distanceM;
  }
  fit.normalAngleRad = std::atan2(fit.normal.y(), fit.normal.x());
  fit.rmsResidualM = std::sqrt(across / count_);

  // d(distance)/d(angle) at the centroid: its coordinate along the line.
  const double variance = count_ > 2.0 ? across / (count_ - 2.0) : 0.0;
  const double angleVariance = variance / along;
  const double along0 = Eigen::Vector2d(-fit.normal.y(), fit.normal.x()).dot(mean_);
  fit.covariance << angleVariance, along0 * angleVariance, along0 * angleVariance,
      variance / count_ + along0 * along0 * angleVariance;
  return fit;
}

}  // namespace rgnav
