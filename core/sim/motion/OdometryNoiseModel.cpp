// OdometryNoiseModel: Table 5.6 variances with the drift terms, in the generative direction.
#include "core/sim/motion/OdometryNoiseModel.h"

#include <cmath>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"

namespace rgnav {

void validate(const OdometryNoiseConfig& config) {
  requireNonNegative(config.alpha1, "odometry alpha1");
  requireNonNegative(config.alpha2, "odometry alpha2");
  requireNonNegative(config.alpha3, "odometry alpha3");
  requireNonNegative(config.alpha4, "odometry alpha4");
  if (!std::isfinite(config.translationScaleError) || config.translationScaleError <= -1.0) {
    throw ConfigError("odometry translation scale error must be finite and greater than -1");
  }
  if (!std::isfinite(config.rotationBiasPerMetre)) {
    throw ConfigError("odometry rotation bias per metre must be finite");
  }
}

OdometryNoiseModel::OdometryNoiseModel(const OdometryNoiseConfig& config, std::uint64_t seed)
    : config_(config), rng_(seed) {
  validate(config_);
}

double OdometryNoiseModel::gaussian(double variance) { return std::sqrt(variance) * normal_(rng_); }

OdometryMotion OdometryNoiseModel::sample(const OdometryMotion& truth) {
  const double r1 = truth.rot1 * truth.rot1;
  const double r2 = truth.rot2 * truth.rot2;
  const double t = truth.trans * truth.trans;
  const double bias = 0.5 * config_.rotationBiasPerMetre * std::abs(truth.trans);
  const double a1 = config_.alpha1, a2 = config_.alpha2, a3 = config_.alpha3, a4 = config_.alpha4;
  // Drawn in a fixed order (rot1, trans, rot2) so a seed fixes the sequence.
  OdometryMotion reported;
  reported.rot1 = truth.rot1 + bias + gaussian(a1 * r1 + a2 * t);
  reported.trans =
      truth.trans * (1.0 + config_.translationScaleError) + gaussian(a3 * t + a4 * (r1 + r2));
  reported.rot2 = truth.rot2 + bias + gaussian(a1 * r2 + a2 * t);
  return reported;
}

Pose2D OdometryNoiseModel::advance(const Pose2D& odometry, const Pose2D& trueFrom,
                                   const Pose2D& trueTo) {
  return applyMotion(odometry, sample(decomposeMotion(trueFrom, trueTo)));
}

std::vector<Pose2D> OdometryNoiseModel::odometryPoses(std::span<const Pose2D> truePoses,
                                                      const Pose2D& odometryStart) {
  std::vector<Pose2D> odometry;
  odometry.reserve(truePoses.size());
  for (std::size_t i = 0; i < truePoses.size(); ++i) {
    odometry.push_back(i == 0 ? odometryStart : advance(odometry.back(), truePoses[i - 1], truePoses[i]));
  }
  return odometry;
}

}  // namespace rgnav
