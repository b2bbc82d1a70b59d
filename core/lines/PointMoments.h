// PointMoments: sufficient statistics of a planar point set (count, mean, scatter matrix) and
// the total-least-squares line fit they define, with the residual spread and the covariance of
// the line parameters. Used for every line fit: split-and-merge in one scan (thesis 5.2,
// "scans are converted to line scans") and line merging (3.1.1).
// Deliberate difference: the thesis (3.1.1) does not say how the merged line is placed; here two
// segments merge by adding their moments, so a merged line is the TLS fit of all points that
// made it, as if they had been fitted together.
#pragma once

#include <Eigen/Core>

namespace rgnav {

// A line in Hesse normal form (normal · p = distanceM, distanceM >= 0) fitted by total least
// squares, with the point that anchors it and its quality.
struct LineFit {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // unit
  Eigen::Vector2d normal = Eigen::Vector2d::UnitY();     // unit, (cos normalAngleRad, sin normalAngleRad)
  double normalAngleRad = 0.0;
  double distanceM = 0.0;
  double rmsResidualM = 0.0;  // root mean square of the orthogonal residuals
  // Covariance of (normalAngleRad, distanceM) for isotropic point noise whose variance is
  // estimated from the residuals (sum of squares / (n - 2); zero for two points).
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
};

class PointMoments {
 public:
  void add(const Eigen::Vector2d& point);
  // Adds the points summarised by `other` (parallel-axis combination, numerically stable).
  void add(const PointMoments& other);

  double count() const { return count_; }
  const Eigen::Vector2d& mean() const { return mean_; }
  // Sum over the points of (p - mean)(p - mean)^T.
  const Eigen::Matrix2d& scatter() const { return scatter_; }

  // Throws InvalidArgumentError for fewer than two points or points that all coincide.
  LineFit fitLine() const;

 private:
  double count_ = 0.0;
  Eigen::Vector2d mean_ = Eigen::Vector2d::Zero();
  Eigen::Matrix2d scatter_ = Eigen::Matrix2d::Zero();
};

}  // namespace rgnav
