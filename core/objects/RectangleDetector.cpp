// Rectangles from quadrangle hypotheses, thesis 3.2; see RectangleDetector.h.
#include "core/objects/RectangleDetector.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/objects/OverlapSuppression.h"

namespace rgnav {
namespace {

// Length of [a0, a1] (either order) inside [lo, hi].
double overlap(double a0, double a1, double lo, double hi) {
  return std::max(0.0, std::min(std::max(a0, a1), hi) - std::max(std::min(a0, a1), lo));
}

}  // namespace

Rectangle2D fitRectangle(const std::vector<LineSegment>& lines, const Quadrangle& q) {
  // Side m of the quadrangle runs from corner m-1 to corner m.
  const auto edgeStart = [&](std::size_t m) { return q.corners[(m + 3) % 4]; };
  const auto edgeEnd = [&](std::size_t m) { return q.corners[m]; };

  // Heading modulo 90 degrees: mean of 4 * edge angle, weighted by edge length.
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (std::size_t m = 0; m < 4; ++m) {
    const Eigen::Vector2d e = edgeEnd(m) - edgeStart(m);
    const double a = 4.0 * std::atan2(e.y(), e.x());
    sum += e.norm() * Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  const double theta = 0.25 * std::atan2(sum.y(), sum.x());
  Eigen::Vector2d u(std::cos(theta), std::sin(theta)), v(-u.y(), u.x());
  // Make sides 0 and 2 the ones along u (offsets measured along v).
  const Eigen::Vector2d e0 = edgeEnd(0) - edgeStart(0);
  if (std::fabs(e0.dot(u)) < std::fabs(e0.dot(v))) std::swap(u, v);

  const auto offset = [&](std::size_t m, const Eigen::Vector2d& axis) {
    return 0.5 * axis.dot(edgeStart(m) + edgeEnd(m));
  };
  const double v0 = offset(0, v), v2 = offset(2, v), u1 = offset(1, u), u3 = offset(3, u);
  const double vLo = std::min(v0, v2), vHi = std::max(v0, v2), uLo = std::min(u1, u3), uHi = std::max(u1, u3);

  Rectangle2D r;
  r.sides = q.sides;
  const Eigen::Vector2d centre = 0.5 * (uLo + uHi) * u + 0.5 * (vLo + vHi) * v;
  const double alongU = uHi - uLo, alongV = vHi - vLo;
  const Eigen::Vector2d lengthAxis = alongU >= alongV ? u : v;
  double heading = std::atan2(lengthAxis.y(), lengthAxis.x());
  if (heading < 0.0) heading += M_PI;
  if (heading >= M_PI) heading -= M_PI;
  r.pose = {centre.x(), centre.y(), heading};
  r.lengthM = std::max(alongU, alongV);
  r.widthM = std::min(alongU, alongV);

  // Perimeter covered: each side's segment projected onto its rectangle edge.
  double covered = 0.0;
  for (std::size_t m = 0; m < 4; ++m) {
    const LineSegment& s = lines.at(q.sides[m]);
    const bool alongUAxis = m % 2 == 0;
    const Eigen::Vector2d& axis = alongUAxis ? u : v;
    covered += alongUAxis ? overlap(axis.dot(s.start), axis.dot(s.end), uLo, uHi)
                          : overlap(axis.dot(s.start), axis.dot(s.end), vLo, vHi);
  }
  const double perimeter = 2.0 * (alongU + alongV);
  r.confidence = perimeter > 0.0 ? std::min(1.0, covered / perimeter) : 0.0;
  return r;
}

Polygon rectangleOutline(const Rectangle2D& r) {
  const Eigen::Vector2d c(r.pose.x, r.pose.y);
  const Eigen::Vector2d u = 0.5 * r.lengthM * Eigen::Vector2d(std::cos(r.pose.theta), std::sin(r.pose.theta));
  const Eigen::Vector2d v = 0.5 * r.widthM * Eigen::Vector2d(-std::sin(r.pose.theta), std::cos(r.pose.theta));
  return {c - u - v, c + u - v, c + u + v, c - u + v};
}

RectangleDetector::RectangleDetector(const RectangleDetectorParams& params)
    : params_(params), grouping_(params.grouping) {
  if (!(params.minConfidence >= 0.0 && params.minConfidence <= 1.0) ||
      !(params.maxOverlapRatio >= 0.0 && params.maxOverlapRatio < 1.0))
    throw InvalidArgumentError("rectangle detector: minConfidence must lie in [0, 1], maxOverlapRatio in [0, 1)");
}

std::vector<Rectangle2D> RectangleDetector::detect(const std::vector<LineSegment>& lines,
                                                   const std::function<bool(const Rectangle2D&)>& keep) const {
  std::vector<Rectangle2D> candidates;
  std::vector<Polygon> outlines;
  std::vector<double> confidences;
  for (const Quadrangle& q : grouping_.twoStage(lines)) {
    Rectangle2D r = fitRectangle(lines, q);
    if (r.confidence < params_.minConfidence || (keep && !keep(r))) continue;
    outlines.push_back(rectangleOutline(r));
    confidences.push_back(r.confidence);
    candidates.push_back(r);
  }
  std::vector<Rectangle2D> kept;
  for (const std::size_t i :
       suppressOverlaps(outlines, confidences, OverlapMeasure::kIntersectionOverUnion, params_.maxOverlapRatio))
    kept.push_back(candidates[i]);
  return kept;
}

}  // namespace rgnav
