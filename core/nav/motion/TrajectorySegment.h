// TrajectorySegment: one trajectory primitive of thesis 5.5.3, described by a few parameters: a
// start pose, a length and a curvature that changes linearly with the arc length s,
//   kappa(s) = curvature + sharpness * s,
// so a straight segment has curvature = sharpness = 0, an arc of a circle sharpness = 0 and a
// clothoid (Euler spiral) sharpness != 0. Heading: theta(s) = theta0 + curvature*s +
// sharpness*s^2/2; position: the Fresnel-type integrals of (cos theta, sin theta), evaluated
// exactly for straights and arcs and to 1e-9 m for clothoids. The robot drives forward along it.
#pragma once

#include "core/common/Pose2D.h"

namespace rgnav {

enum class SegmentKind { Straight, Arc, Clothoid };

struct TrajectorySegment {
  Pose2D start;
  double length = 0.0;     // m, > 0
  double curvature = 0.0;  // 1/m at s = 0, positive = turning left
  double sharpness = 0.0;  // 1/m^2: d kappa / d s

  SegmentKind kind() const;
  double curvatureAt(double s) const { return curvature + sharpness * s; }
  // The pose at arc length s in [0, length] (clamped).
  Pose2D poseAt(double s) const;
  Pose2D end() const { return poseAt(length); }

  friend bool operator==(const TrajectorySegment&, const TrajectorySegment&) = default;
};

// Throws InvalidArgumentError for a non-positive or non-finite length or non-finite values.
void validate(const TrajectorySegment& segment);

}  // namespace rgnav
