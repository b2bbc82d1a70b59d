// Construction and geometry of line segments; see LineSegment.h.
#include "core/lines/LineSegment.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

Eigen::Vector2d LineSegment::direction() const {
  const Eigen::Vector2d d = end - start;
  const double n = d.norm();
  return n > 0.0 ? Eigen::Vector2d(d / n) : Eigen::Vector2d::Zero();
}

double LineSegment::orientationRad() const {
  const Eigen::Vector2d d = end - start;
  double a = std::atan2(d.y(), d.x());
  if (a < 0.0) a += M_PI;
  return a >= M_PI ? 0.0 : a;
}

Eigen::Vector2d projectOntoLine(const LineFit& fit, const Eigen::Vector2d& p) {
  return fit.centroid + fit.direction * fit.direction.dot(p - fit.centroid);
}

double orientationDifference(double a, double b) {
  const double d = std::fmod(std::fabs(a - b), M_PI);
  return std::min(d, M_PI - d);
}

LineSegment segmentFromPoints(SegmentId id, std::span<const Eigen::Vector2d> points) {
  LineSegment segment;
  segment.id = id;
  for (const auto& p : points) segment.moments.add(p);
  const LineFit fit = segment.moments.fitLine();
  segment.start = projectOntoLine(fit, points.front());
  segment.end = projectOntoLine(fit, points.back());
  segment.provenance = {id};
  return segment;
}

LineSegment segmentFromEndpoints(SegmentId id, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  if (a == b) throw InvalidArgumentError("segment with identical endpoints");
  LineSegment segment;
  segment.id = id;
  segment.start = a;
  segment.end = b;
  segment.moments.add(a);
  segment.moments.add(b);
  segment.provenance = {id};
  return segment;
}

}  // namespace rgnav
