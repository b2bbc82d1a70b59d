// Angle and distance between line segments, thesis 3.1; see SegmentRelations.h.
#include "core/objects/SegmentRelations.h"

#include <algorithm>
#include <cmath>

namespace rgnav {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Distance of p from the closed segment s.
double pointToSegment(const Eigen::Vector2d& p, const LineSegment& s) {
  const Eigen::Vector2d d = s.end - s.start;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - s.start).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (s.start + t * d - p).norm();
}

}  // namespace

double minAngle(const LineSegment& a, const LineSegment& b) {
  const Eigen::Vector2d u = a.end - a.start, v = b.end - b.start;
  // atan2(|u x v|, |u . v|) is the angle between the lines folded into [0, pi/2].
  return std::atan2(std::fabs(cross(u, v)), std::fabs(u.dot(v)));
}

std::optional<Eigen::Vector2d> lineIntersection(const LineSegment& a, const LineSegment& b) {
  const Eigen::Vector2d u = a.end - a.start, v = b.end - b.start;
  const double den = cross(u, v);
  if (std::fabs(den) <= 1e-12 * u.norm() * v.norm()) return std::nullopt;
  return a.start + u * (cross(b.start - a.start, v) / den);
}

double segmentDistance(const LineSegment& a, const LineSegment& b) {
  double best = std::min(
      {pointToSegment(a.start, b), pointToSegment(a.end, b), pointToSegment(b.start, a), pointToSegment(b.end, a)});
  if (const auto x = lineIntersection(a, b))
    best = std::min(best, std::max(pointToSegment(*x, a), pointToSegment(*x, b)));
  return best;
}

}  // namespace rgnav
