// Convex hull, area and intersection; see ConvexPolygon.h.
#include "core/objects/ConvexPolygon.h"

#include <algorithm>

namespace rgnav {
namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

Polygon convexHull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(),
            [](const auto& a, const auto& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  if (points.size() < 3) return points;
  Polygon hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {  // lower hull
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper hull
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

double polygonArea(const Polygon& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const auto& a = polygon[i];
    const auto& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

double intersectionArea(const Polygon& a, const Polygon& b) {
  Polygon clipped = a;
  for (std::size_t e = 0; e < b.size() && !clipped.empty(); ++e) {
    const Eigen::Vector2d& p = b[e];
    const Eigen::Vector2d& q = b[(e + 1) % b.size()];
    Polygon next;
    for (std::size_t i = 0; i < clipped.size(); ++i) {
      const Eigen::Vector2d& s = clipped[i];
      const Eigen::Vector2d& t = clipped[(i + 1) % clipped.size()];
      const double ds = cross(p, q, s), dt = cross(p, q, t);
      if (ds >= 0.0) next.push_back(s);
      if ((ds >= 0.0) != (dt >= 0.0)) next.push_back(s + (t - s) * (ds / (ds - dt)));
    }
    clipped = std::move(next);
  }
  return clipped.size() < 3 ? 0.0 : polygonArea(clipped);
}

bool insideConvex(const Polygon& polygon, const Eigen::Vector2d& p, double marginM) {
  if (polygon.size() < 3) return false;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d edge = polygon[(i + 1) % polygon.size()] - a;
    const double cross = edge.x() * (p.y() - a.y()) - edge.y() * (p.x() - a.x());
    if (cross < -marginM * edge.norm()) return false;  // farther than marginM right of the edge
  }
  return true;
}

}  // namespace rgnav
