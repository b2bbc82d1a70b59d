// Circle fitting to 2D points: an algebraic fit (Kasa: linear least squares on
// x^2 + y^2 + D x + E y + F = 0, in coordinates centred on the points) as the start, refined
// by Levenberg-Marquardt on the geometric distances |p - c| - r. For round objects in region
// descriptions (thesis Table 2.1, "2D circle": round tables, bins); the thesis gives no method.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>

namespace rgnav {

struct CircleFit {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double radiusM = 0.0;
  double rmsResidualM = 0.0;  // root mean square of the geometric residuals
};

// nullopt for fewer than three points or points on a line (no finite circle).
std::optional<CircleFit> fitCircleAlgebraic(std::span<const Eigen::Vector2d> points);
std::optional<CircleFit> fitCircle(std::span<const Eigen::Vector2d> points);

}  // namespace rgnav
