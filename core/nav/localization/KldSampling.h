// KldSampling: the particle count of KLD-sampling (Fox, "Adapting the sample size in particle
// filters through KLD-sampling", IJRR 2003, eq. 12 with the Wilson-Hilferty approximation):
//   n = (k - 1) / (2 eps) * (1 - 2 / (9 (k - 1)) + sqrt(2 / (9 (k - 1))) z)^3
// for k occupied bins of the (x, y, theta) histogram (KldConfig bin sizes), clamped to
// [minParticles, maxParticles]. KldBins counts the occupied bins of a particle set as it grows.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_set>

#include "core/common/Pose2D.h"
#include "core/nav/localization/MclConfig.h"

namespace rgnav {

// The KLD bound for k occupied bins (k <= 1: minParticles).
std::size_t kldParticleBound(std::size_t occupiedBins, const KldConfig& config);

class KldBins {
 public:
  explicit KldBins(const KldConfig& config) : config_(config) {}
  // Adds a pose (map frame; `region` keeps the bins of different regions apart); true if its bin was empty.
  bool add(std::uint64_t region, const Pose2D& mapPose);
  std::size_t occupied() const { return bins_.size(); }

 private:
  KldConfig config_;
  std::unordered_set<std::uint64_t> bins_;
};

}  // namespace rgnav
