// Per-increment Gaussian perturbation with a seeded Mersenne twister.
#include "core/slam/eval/OdometryNoise.h"

#include <cmath>
#include <random>

namespace rgnav {

std::vector<Pose2D> noisyOdometry(std::span<const Pose2D> reference, const OdometryNoiseConfig& config,
                                  std::uint64_t seed) {
  std::vector<Pose2D> odometry;
  if (reference.empty()) return odometry;
  std::mt19937_64 random(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  odometry.push_back(reference.front());
  for (std::size_t i = 1; i < reference.size(); ++i) {
    const Pose2D step = between(reference[i - 1], reference[i]);
    const double distance = std::hypot(step.x, step.y);
    const double turn = std::abs(step.theta);
    const double sigmaTranslation = config.translationPerSqrtMetre * std::sqrt(distance);
    const double sigmaRotation = std::sqrt(config.rotationPerSqrtMetre * config.rotationPerSqrtMetre * distance +
                                           config.rotationPerSqrtRadian * config.rotationPerSqrtRadian * turn);
    const Pose2D noisy{step.x + sigmaTranslation * unit(random), step.y + sigmaTranslation * unit(random),
                       step.theta + sigmaRotation * unit(random)};
    odometry.push_back(compose(odometry.back(), noisy));
  }
  return odometry;
}

}  // namespace rgnav
