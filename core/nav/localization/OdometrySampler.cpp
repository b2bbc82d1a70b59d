// OdometrySampler (OdometrySampler.h): Table 5.6 of Thrun et al., with the rotations of a motion
// shorter than kMinOdometryTranslation taken as one turn (rot1 = 0) by the decomposition.
#include "core/nav/localization/OdometrySampler.h"

#include <cmath>

namespace rgnav {

OdometrySampler::OdometrySampler(const MotionModelConfig& config, std::uint64_t seed) : config_(config), rng_(seed) {
  MclConfig whole;
  whole.motion = config;
  validate(whole);
}

Pose2D OdometrySampler::sample(const Pose2D& pose, const OdometryMotion& motion) {
  const double r1 = motion.rot1 * motion.rot1, r2 = motion.rot2 * motion.rot2, t = motion.trans * motion.trans;
  const auto noisy = [&](double value, double variance) { return value - std::sqrt(variance) * normal_(rng_); };
  OdometryMotion sampled;
  sampled.rot1 = noisy(motion.rot1, config_.alpha1 * r1 + config_.alpha2 * t);
  sampled.trans = noisy(motion.trans, config_.alpha3 * t + config_.alpha4 * (r1 + r2));
  sampled.rot2 = noisy(motion.rot2, config_.alpha1 * r2 + config_.alpha2 * t);
  return applyMotion(pose, sampled);
}

}  // namespace rgnav
