// noisyOdometry: synthetic raw odometry for logs that only have corrected poses: the reference
// trajectory's increments, each perturbed in the robot frame with zero-mean Gaussian noise and
// accumulated, so the error drifts like wheel odometry. Differs from the odometry motion model of
// Thrun et al. (Probabilistic Robotics 5.4, standard deviations proportional to the motion): here
// variances are proportional to the motion (a random walk per metre and per radian), so the drift
// over a path does not depend on how densely the log samples it. Seeded: the same seed gives the
// same odometry.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/common/Pose2D.h"

namespace rgnav {

struct OdometryNoiseConfig {
  double translationPerSqrtMetre = 0.05;  // m standard deviation after 1 m, along and across
  double rotationPerSqrtMetre = 0.03;     // rad standard deviation after 1 m
  double rotationPerSqrtRadian = 0.05;    // rad standard deviation after turning 1 rad
};

// Same length as `reference`; starts at reference[0].
std::vector<Pose2D> noisyOdometry(std::span<const Pose2D> reference, const OdometryNoiseConfig& config,
                                  std::uint64_t seed);

}  // namespace rgnav
