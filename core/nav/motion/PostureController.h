// PostureController: the Lyapunov-stable tracking control law for a unicycle of Kanayama,
// Kimura, Miyazaki and Noguchi ("A stable tracking control method for an autonomous mobile
// robot", ICRA 1990), thesis 5.5.3 [54]: with the error of the reference posture in the robot's
// frame (e_x, e_y, e_theta) and the reference speeds (v_r, w_r),
//   v = v_r cos(e_theta) + K_x e_x
//   w = w_r + v_r (K_y e_y + K_theta sin(e_theta)),
// V = (e_x^2 + e_y^2) + 2 (1 - cos e_theta) / K_y is a Lyapunov function for K_x, K_y, K_theta > 0
// and v_r > 0. The commands are clamped to the limits afterwards.
#pragma once

#include "core/common/Pose2D.h"
#include "core/common/VelocityCommand.h"
#include "core/nav/motion/MotionLimits.h"

namespace rgnav {

struct PostureGains {
  double kx = 2.0;      // 1/s
  double ky = 20.0;     // 1/m^2
  double ktheta = 6.0;  // 1/m
};

// Throws ConfigError for a gain that is not positive and finite.
void validate(const PostureGains& gains);

// The posture error of `reference` seen from `robot`: (e_x, e_y) in the robot's frame, e_theta
// the heading difference in (-pi, pi].
Pose2D postureError(const Pose2D& robot, const Pose2D& reference);

class PostureController {
 public:
  PostureController(const PostureGains& gains, const MotionLimits& limits);
  VelocityCommand command(const Pose2D& robot, const Pose2D& reference, double referenceVelocity,
                          double referenceRotational) const;

 private:
  PostureGains gains_;
  MotionLimits limits_;
};

}  // namespace rgnav
