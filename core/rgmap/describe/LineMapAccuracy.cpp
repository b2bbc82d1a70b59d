// Fit of a line map to the measurements of its region; see LineMapAccuracy.h.
#include "core/rgmap/describe/LineMapAccuracy.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

// A segment prepared for many point distances.
struct Segment {
  Eigen::Vector2d start;
  Eigen::Vector2d direction;  // unit (zero for a degenerate segment)
  double length;
};

double squaredDistance(const Eigen::Vector2d& p, const Segment& s) {
  const Eigen::Vector2d v = p - s.start;
  const double along = std::clamp(v.dot(s.direction), 0.0, s.length);
  return (v - along * s.direction).squaredNorm();
}

}  // namespace

LineMapAccuracy lineMapAccuracy(std::span<const Eigen::Vector2d> points, std::span<const LineSegment> lines,
                                const AccuracyParams& params) {
  if (!(params.toleranceM > 0.0) || !(params.toleranceM <= params.maxDistanceM) || !std::isfinite(params.maxDistanceM))
    throw InvalidArgumentError("line map accuracy: need 0 < toleranceM <= maxDistanceM, both finite");
  std::vector<Segment> segments;
  segments.reserve(lines.size());
  for (const LineSegment& l : lines) segments.push_back({l.start, l.direction(), l.length()});

  LineMapAccuracy out;
  out.pointCount = points.size();
  if (points.empty()) return out;
  const double clampSquared = params.maxDistanceM * params.maxDistanceM;
  const double toleranceSquared = params.toleranceM * params.toleranceM;
  std::size_t inliers = 0;
  double sum = 0.0, sumSquares = 0.0;
  for (const Eigen::Vector2d& p : points) {
    double best = clampSquared;
    for (const Segment& s : segments) best = std::min(best, squaredDistance(p, s));
    inliers += best <= toleranceSquared;
    sum += std::sqrt(best);
    sumSquares += best;
  }
  const double n = double(points.size());
  out.inlierShare = double(inliers) / n;
  out.meanDistanceM = sum / n;
  out.rmsDistanceM = std::sqrt(sumSquares / n);
  return out;
}

}  // namespace rgnav
