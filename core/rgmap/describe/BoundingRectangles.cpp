// Bounding rectangles of a convex hull; see BoundingRectangles.h.
#include "core/rgmap/describe/BoundingRectangles.h"

#include <cmath>

namespace rgnav {

std::array<Eigen::Vector2d, 4> OrientedRectangle::corners() const {
  const Eigen::Vector2d u = 0.5 * lengthM * Eigen::Vector2d(std::cos(angleRad), std::sin(angleRad));
  const Eigen::Vector2d v = 0.5 * widthM * Eigen::Vector2d(-std::sin(angleRad), std::cos(angleRad));
  return {center - u - v, center + u - v, center + u + v, center - u + v};
}

Eigen::AlignedBox2d axisAlignedBox(const Polygon& hull) {
  Eigen::AlignedBox2d box;
  for (const Eigen::Vector2d& p : hull) box.extend(p);
  return box;
}

std::optional<OrientedRectangle> minimumAreaRectangle(const Polygon& hull) {
  if (hull.empty()) return std::nullopt;
  std::optional<OrientedRectangle> best;
  for (std::size_t e = 0; e < hull.size(); ++e) {
    const Eigen::Vector2d edge = hull[(e + 1) % hull.size()] - hull[e];
    // A single point (or a closing edge of length zero) is measured along the x-axis.
    const Eigen::Vector2d u = edge.norm() > 0.0 ? Eigen::Vector2d(edge.normalized()) : Eigen::Vector2d::UnitX();
    const Eigen::Vector2d v(-u.y(), u.x());
    Eigen::AlignedBox2d extent;  // in (u, v) coordinates
    for (const Eigen::Vector2d& p : hull) extent.extend(Eigen::Vector2d(u.dot(p), v.dot(p)));
    const Eigen::Vector2d size = extent.sizes();
    if (best && size.prod() >= best->areaM2()) continue;
    const Eigen::Vector2d mid = extent.center();
    const bool alongU = size.x() >= size.y();
    const Eigen::Vector2d lengthDirection = alongU ? u : v;
    double angle = std::atan2(lengthDirection.y(), lengthDirection.x());
    if (angle < 0.0) angle += M_PI;
    best = OrientedRectangle{mid.x() * u + mid.y() * v, angle >= M_PI ? 0.0 : angle, size.maxCoeff(),
                             size.minCoeff()};
  }
  return best;
}

}  // namespace rgnav
