// PostureController: Kanayama's tracking law (see the header), clamped to the top speeds.
#include "core/nav/motion/PostureController.h"

#include <algorithm>
#include <cmath>

#include "core/common/ValueChecks.h"

namespace rgnav {

void validate(const PostureGains& gains) {
  requirePositive(gains.kx, "posture gain kx");
  requirePositive(gains.ky, "posture gain ky");
  requirePositive(gains.ktheta, "posture gain ktheta");
}

Pose2D postureError(const Pose2D& robot, const Pose2D& reference) { return between(robot, reference); }

PostureController::PostureController(const PostureGains& gains, const MotionLimits& limits)
    : gains_(gains), limits_(limits) {
  validate(gains_);
  validate(limits_);
}

VelocityCommand PostureController::command(const Pose2D& robot, const Pose2D& reference,
                                           double referenceVelocity, double referenceRotational) const {
  const Pose2D e = postureError(robot, reference);
  const double v = referenceVelocity * std::cos(e.theta) + gains_.kx * e.x;
  const double w = referenceRotational +
                   referenceVelocity * (gains_.ky * e.y + gains_.ktheta * std::sin(e.theta));
  return {std::clamp(v, -limits_.maxVelocity, limits_.maxVelocity),
          std::clamp(w, -limits_.maxRotationalVelocity, limits_.maxRotationalVelocity)};
}

}  // namespace rgnav
