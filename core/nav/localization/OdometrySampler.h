// OdometrySampler: sample_motion_model_odometry (Thrun, Burgard, Fox, Probabilistic Robotics 2005,
// 5.4, Table 5.6): a particle's new pose from the odometry's motion between two readings, with
// the four-alpha noise. The rot1/trans/rot2 decomposition is the simulator's (OdometryMotion.h),
// so reversing is a negative translation, not a half turn.
#pragma once

#include <cstdint>
#include <random>

#include "core/common/Pose2D.h"
#include "core/nav/localization/MclConfig.h"
#include "core/common/OdometryMotion.h"

namespace rgnav {

class OdometrySampler {
 public:
  // Throws ConfigError for a negative or non-finite alpha.
  OdometrySampler(const MotionModelConfig& config, std::uint64_t seed);

  // A sample of the pose reached from `pose` when the odometry moved by `motion`.
  Pose2D sample(const Pose2D& pose, const OdometryMotion& motion);

 private:
  MotionModelConfig config_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace rgnav
