// LineSegment: a 2D line segment of a line map (thesis 3.1, 5.2): endpoints on its TLS-fitted
// line, the moments of the points it was fitted to (fit quality and covariance), and its
// provenance, the IDs of the original segments merged into it, so that a merge can be
// reversed (3.3.1). Its support is the number of those original segments.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "core/lines/PointMoments.h"

namespace rgnav {

using SegmentId = std::uint64_t;

struct LineSegment {
  SegmentId id = 0;
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  Eigen::Vector2d end = Eigen::Vector2d::Zero();
  PointMoments moments;
  std::vector<SegmentId> provenance;  // sorted IDs of the original segments

  double length() const { return (end - start).norm(); }
  // Unit vector from start to end (zero for a degenerate segment).
  Eigen::Vector2d direction() const;
  // Angle of the undirected segment to the x-axis, in [0, pi).
  double orientationRad() const;
  std::size_t support() const { return provenance.size(); }
  // TLS fit quality and covariance of the points behind the segment.
  LineFit fit() const { return moments.fitLine(); }
};

// An original segment fitted to `points` (at least two, not all equal): the endpoints are the
// first and last point projected onto the fitted line. Provenance {id}.
LineSegment segmentFromPoints(SegmentId id, std::span<const Eigen::Vector2d> points);

// An original segment known only by its endpoints (e.g. from an image edge detector); its
// moments are those of the two endpoints. Provenance {id}. Throws if a == b.
LineSegment segmentFromEndpoints(SegmentId id, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

// The orthogonal projection of `p` onto the infinite line of `fit`.
Eigen::Vector2d projectOntoLine(const LineFit& fit, const Eigen::Vector2d& p);

// Smallest difference between two undirected orientations in [0, pi): in [0, pi/2].
double orientationDifference(double a, double b);

}  // namespace rgnav
