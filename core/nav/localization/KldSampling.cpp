// KLD-sampling bound and bins (KldSampling.h).
#include "core/nav/localization/KldSampling.h"

#include <algorithm>
#include <cmath>

namespace rgnav {

std::size_t kldParticleBound(std::size_t occupiedBins, const KldConfig& config) {
  if (occupiedBins <= 1) return config.minParticles;
  const double k1 = static_cast<double>(occupiedBins - 1);
  const double a = 2.0 / (9.0 * k1);
  const double n = k1 / (2.0 * config.epsilon) * std::pow(1.0 - a + std::sqrt(a) * config.upperQuantile, 3.0);
  const double clamped = std::clamp(std::ceil(n), static_cast<double>(config.minParticles),
                                    static_cast<double>(config.maxParticles));
  return static_cast<std::size_t>(clamped);
}

bool KldBins::add(std::uint64_t region, const Pose2D& mapPose) {
  const auto bin = [](double value, double size) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(value / size)) & 0xFFFFF);
  };
  const std::uint64_t key = (region << 60) ^ (bin(mapPose.x, config_.binXyM) << 40) ^
                            (bin(mapPose.y, config_.binXyM) << 20) ^ bin(mapPose.theta + M_PI, config_.binThetaRad);
  return bins_.insert(key).second;
}

}  // namespace rgnav
