// Validation of the localization parameters (MclConfig.h).
#include "core/nav/localization/MclConfig.h"

#include "core/common/ValueChecks.h"

namespace rgnav {
namespace {

void requireProbability(double value, const std::string& what) {
  if (!(value >= 0.0 && value <= 1.0)) throw ConfigError(what + " must lie in [0, 1]");
}

void requireCount(std::size_t value, const std::string& what) {
  if (value == 0) throw ConfigError(what + " must be at least 1");
}

}  // namespace

void validate(const MclConfig& config) {
  const BeamModelConfig& beam = config.beam;
  requirePositive(beam.resolutionM, "beam.resolution_m");
  requirePositive(beam.sigmaHitM, "beam.sigma_hit_m");
  requireProbability(beam.zHit, "beam.z_hit");
  requireProbability(beam.zRand, "beam.z_rand");
  if (!(beam.zRand > 0.0)) throw ConfigError("beam.z_rand must be positive (a beam's likelihood must never be 0)");
  requirePositive(beam.maxRangeM, "beam.max_range_m");
  requireNonNegative(beam.marginM, "beam.margin_m");
  requireCount(beam.beams, "beam.beams");
  requireCount(beam.overlapMinCells, "beam.overlap_min_cells");
  requirePositive(beam.beamWeight, "beam.beam_weight");
  for (const double alpha : {config.motion.alpha1, config.motion.alpha2, config.motion.alpha3, config.motion.alpha4})
    requireNonNegative(alpha, "motion.alpha");
  const KldConfig& kld = config.kld;
  requireCount(kld.minParticles, "kld.min_particles");
  if (kld.maxParticles < kld.minParticles) throw ConfigError("kld.max_particles must be at least kld.min_particles");
  requirePositive(kld.epsilon, "kld.epsilon");
  requirePositive(kld.upperQuantile, "kld.upper_quantile");
  requirePositive(kld.binXyM, "kld.bin_xy_m");
  requirePositive(kld.binThetaRad, "kld.bin_theta_rad");
  requireNonNegative(config.updateMinTravelM, "update_min_travel_m");
  requireNonNegative(config.updateMinTurnRad, "update_min_turn_rad");
  requireProbability(config.resampleBelowEss, "resample_below_ess");
  requirePositive(config.handoverRadiusM, "handover_radius_m");
  requireNonNegative(config.traversalConfirmM, "traversal_confirm_m");
  requirePositive(config.clusterRadiusM, "cluster_radius_m");
  requirePositive(config.clusterAngleRad, "cluster_angle_rad");
}

}  // namespace rgnav
