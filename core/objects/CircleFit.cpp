// Algebraic and geometric circle fits; see CircleFit.h.
#include "core/objects/CircleFit.h"

#include <Eigen/Dense>
#include <cmath>

namespace rgnav {
namespace {

double rms(std::span<const Eigen::Vector2d> points, const Eigen::Vector2d& c, double r) {
  double sum = 0.0;
  for (const auto& p : points) sum += std::pow((p - c).norm() - r, 2);
  return std::sqrt(sum / double(points.size()));
}

}  // namespace

std::optional<CircleFit> fitCircleAlgebraic(std::span<const Eigen::Vector2d> points) {
  if (points.size() < 3) return std::nullopt;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : points) mean += p;
  mean /= double(points.size());
  // Minimise sum (x^2 + y^2 + D x + E y + F)^2 over D, E, F in centred coordinates.
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (const auto& p : points) {
    const Eigen::Vector2d q = p - mean;
    const Eigen::Vector3d row(q.x(), q.y(), 1.0);
    normal += row * row.transpose();
    rhs -= row * q.squaredNorm();
  }
  const auto solver = normal.fullPivLu();
  if (!solver.isInvertible() || solver.rcond() < 1e-12) return std::nullopt;
  const Eigen::Vector3d def = solver.solve(rhs);
  const Eigen::Vector2d center(-0.5 * def(0), -0.5 * def(1));
  const double r2 = center.squaredNorm() - def(2);
  if (!(r2 > 0.0) || !std::isfinite(r2)) return std::nullopt;
  CircleFit fit{center + mean, std::sqrt(r2), 0.0};
  fit.rmsResidualM = rms(points, fit.center, fit.radiusM);
  return fit;
}

std::optional<CircleFit> fitCircle(std::span<const Eigen::Vector2d> points) {
  auto fit = fitCircleAlgebraic(points);
  if (!fit) return std::nullopt;
  Eigen::Vector3d x(fit->center.x(), fit->center.y(), fit->radiusM);
  double cost = std::pow(fit->rmsResidualM, 2);
  double lambda = 1e-3;
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
    Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
    for (const auto& p : points) {
      const Eigen::Vector2d d = p - x.head<2>();
      const double n = d.norm();
      if (n <= 0.0) continue;
      const Eigen::Vector3d j(-d.x() / n, -d.y() / n, -1.0);
      jtj += j * j.transpose();
      jtr += j * (n - x(2));
    }
    // Raise the damping until a step lowers the cost; stop when none does or the gain is nil.
    double gain = 0.0;
    for (; lambda < 1e8; lambda *= 10) {
      Eigen::Matrix3d damped = jtj;
      damped.diagonal() *= 1.0 + lambda;
      const Eigen::Vector3d candidate = x - damped.ldlt().solve(jtr);
      const double c = std::pow(rms(points, candidate.head<2>(), candidate(2)), 2);
      if (std::isfinite(c) && c < cost) {
        gain = cost - c;
        x = candidate, cost = c, lambda = std::max(1e-9, lambda / 10);
        break;
      }
    }
    if (gain <= 1e-15) break;
  }
  if (!(x(2) > 0.0)) return std::nullopt;
  return CircleFit{x.head<2>(), x(2), std::sqrt(cost)};
}

}  // namespace rgnav
