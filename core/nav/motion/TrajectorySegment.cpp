// TrajectorySegment: poses along straights and arcs in closed form, along clothoids by the
// quadrature of ClothoidIntegrals.
#include "core/nav/motion/TrajectorySegment.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/nav/motion/ClothoidIntegrals.h"

namespace rgnav {

namespace {

double sinc(double x) { return std::abs(x) < 1e-4 ? 1.0 - x * x / 6.0 : std::sin(x) / x; }

}  // namespace

SegmentKind TrajectorySegment::kind() const {
  if (sharpness != 0.0) return SegmentKind::Clothoid;
  return curvature != 0.0 ? SegmentKind::Arc : SegmentKind::Straight;
}

Pose2D TrajectorySegment::poseAt(double s) const {
  s = std::clamp(s, 0.0, length);
  const double heading = normalizeAngle(start.theta + s * (curvature + 0.5 * sharpness * s));
  if (sharpness == 0.0) {
    // The chord of the arc (a straight for curvature 0) points along the mean heading.
    const double turn = curvature * s;
    const double chord = s * sinc(0.5 * turn);
    const double mean = start.theta + 0.5 * turn;
    return {start.x + chord * std::cos(mean), start.y + chord * std::sin(mean), heading};
  }
  const PlanarVector d = clothoidDisplacement(s, start.theta, curvature, sharpness);
  return {start.x + d.x, start.y + d.y, heading};
}

void validate(const TrajectorySegment& segment) {
  if (!(std::isfinite(segment.length) && segment.length > 0.0)) {
    throw InvalidArgumentError("trajectory segment: length must be positive and finite");
  }
  if (!(std::isfinite(segment.start.x) && std::isfinite(segment.start.y) &&
        std::isfinite(segment.start.theta))) {
    throw InvalidArgumentError("trajectory segment: start pose must be finite");
  }
  if (!(std::isfinite(segment.curvature) && std::isfinite(segment.sharpness))) {
    throw InvalidArgumentError("trajectory segment: curvature and sharpness must be finite");
  }
}

}  // namespace rgnav
