// MotionLimits: what a differential-drive robot can do: top speeds and accelerations. The
// velocity profile of a trajectory chain (TimedTrajectory) keeps within them, the Low-Level Drive
// never commands beyond them, and the Collision Avoidance plans with them.
#pragma once

namespace rgnav {

struct MotionLimits {
  double maxVelocity = 1.0;                // m/s, forward
  double maxAcceleration = 0.5;            // m/s^2, speeding up
  double maxDeceleration = 0.5;            // m/s^2, braking (a planned stop uses this)
  double maxRotationalVelocity = 1.5708;   // rad/s
  double maxRotationalAcceleration = 1.5708;  // rad/s^2
  double maxLateralAcceleration = 1.0;     // m/s^2: v^2 * |curvature| on arcs
};

// Throws ConfigError naming the first value that is not positive and finite.
void validate(const MotionLimits& limits);

}  // namespace rgnav
