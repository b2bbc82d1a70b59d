// A line segment from centre, orientation and length (see CentredSegment.h).
#include "core/lines/testing/CentredSegment.h"

#include <cmath>

namespace rgnav::testing {

LineSegment centredSegment(SegmentId id, const Eigen::Vector2d& center, double angle, double length) {
  const Eigen::Vector2d h = 0.5 * length * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  return segmentFromEndpoints(id, center - h, center + h);
}

}  // namespace rgnav::testing
