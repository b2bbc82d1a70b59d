// The two relations between line segments that 2D line grouping uses (thesis 3.1):
// - minAngle(li, lj), "min{angle(li, lj)}": the smaller of the two intersection angles of the
//   lines through li and lj, in [0, pi/2]. With this definition an upper bound alpha_max >= 90
//   degrees never rejects a pair; it is kept as a parameter as in the thesis.
// - segmentDistance(li, lj), "distance(li, lj)": zero if the segments really intersect;
//   otherwise the minimum over the distances of each end point to the other segment and, for
//   non-parallel lines, the distance of the virtual intersection to the segments.
// Our reading of "distance of the virtual intersection": the larger of its distances to the two
// segments, i.e. how far the segments must be extended to meet. This is zero exactly for a real
// intersection, as the thesis requires, and it is the gap of an open corner (two segments
// ending 10 cm short of their common corner are 10 cm apart, not 14).
#pragma once

#include <Eigen/Core>
#include <optional>

#include "core/lines/LineSegment.h"

namespace rgnav {

double minAngle(const LineSegment& a, const LineSegment& b);

double segmentDistance(const LineSegment& a, const LineSegment& b);

// The intersection of the infinite lines through a and b; nullopt if they are parallel.
std::optional<Eigen::Vector2d> lineIntersection(const LineSegment& a, const LineSegment& b);

}  // namespace rgnav
