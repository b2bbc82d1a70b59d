// PlanarLine geometry; see PlanarLine.h.
#include "core/gateways/vlm/PlanarLine.h"

#include <cmath>

namespace rgnav {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

std::optional<PlanarLine> lineThrough(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const Eigen::Vector2d d = to - from;
  if (!(d.norm() > 1e-6)) return std::nullopt;
  return PlanarLine{from, d.normalized()};
}

std::optional<Eigen::Vector2d> intersect(const PlanarLine& a, const PlanarLine& b, double minSine) {
  const double den = cross(a.direction, b.direction);
  if (std::fabs(den) < minSine) return std::nullopt;
  const double t = cross(b.point - a.point, b.direction) / den;
  return a.point + t * a.direction;
}

std::optional<double> rayDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& ray, const PlanarLine& line) {
  const double towards = line.leftNormal().dot(ray);
  if (std::fabs(towards) < 1e-12) return std::nullopt;
  const double t = -line.signedOffset(origin) / towards;
  if (t <= 0.0) return std::nullopt;
  return t;
}

double angleBetween(const PlanarLine& a, const PlanarLine& b) {
  const double c = std::fabs(a.direction.dot(b.direction));
  return std::acos(std::min(1.0, c));
}

}  // namespace rgnav
