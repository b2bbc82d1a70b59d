// MotionLimits: the check that every limit is a positive finite number.
#include "core/nav/motion/MotionLimits.h"

#include "core/common/ValueChecks.h"

namespace rgnav {

void validate(const MotionLimits& limits) {
  requirePositive(limits.maxVelocity, "maximum velocity");
  requirePositive(limits.maxAcceleration, "maximum acceleration");
  requirePositive(limits.maxDeceleration, "maximum deceleration");
  requirePositive(limits.maxRotationalVelocity, "maximum rotational velocity");
  requirePositive(limits.maxRotationalAcceleration, "maximum rotational acceleration");
  requirePositive(limits.maxLateralAcceleration, "maximum lateral acceleration");
}

}  // namespace rgnav
