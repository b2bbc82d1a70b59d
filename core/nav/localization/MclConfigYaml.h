// The Localization module's parameters from YAML (config/modules/localization.yaml): every key of
// MclConfig (MclConfig.h) with its beam model, motion model and KLD sections required, no other
// key allowed, validated as the region MCL validates them (validate(MclConfig)). Angles are in
// radians (the keys say so), so the file reads back to exactly the code's values. Errors are
// ConfigErrors naming the file, the key path and the line (DescribedConfig.h).
#pragma once

#include <string>

#include "core/nav/localization/MclConfig.h"

namespace rgnav {

template <class V>
void describe(V& v, BeamModelConfig& c) {
  v.field("resolution_m", c.resolutionM);
  v.field("sigma_hit_m", c.sigmaHitM);
  v.field("z_hit", c.zHit);
  v.field("z_rand", c.zRand);
  v.field("max_range_m", c.maxRangeM);
  v.field("margin_m", c.marginM);
  v.field("overlap_min_cells", c.overlapMinCells);
  v.field("beams", c.beams);
  v.field("beam_weight", c.beamWeight);
}

template <class V>
void describe(V& v, MotionModelConfig& c) {
  v.field("alpha1", c.alpha1);
  v.field("alpha2", c.alpha2);
  v.field("alpha3", c.alpha3);
  v.field("alpha4", c.alpha4);
}

template <class V>
void describe(V& v, KldConfig& c) {
  v.field("min_particles", c.minParticles);
  v.field("max_particles", c.maxParticles);
  v.field("epsilon", c.epsilon);
  v.field("upper_quantile", c.upperQuantile);
  v.field("bin_xy_m", c.binXyM);
  v.field("bin_theta_rad", c.binThetaRad);
}

template <class V>
void describe(V& v, MclConfig& c) {
  v.field("update_min_travel_m", c.updateMinTravelM);
  v.field("update_min_turn_rad", c.updateMinTurnRad);
  v.field("resample_below_ess", c.resampleBelowEss);
  v.field("handover_radius_m", c.handoverRadiusM);
  v.field("traversal_confirm_m", c.traversalConfirmM);
  v.field("cluster_radius_m", c.clusterRadiusM);
  v.field("cluster_angle_rad", c.clusterAngleRad);
  v.section("beam", c.beam);
  v.section("motion", c.motion);
  v.section("kld", c.kld);
}

// `path` names the text in errors.
MclConfig parseMclConfig(const std::string& yamlText, const std::string& path);
// FileError if the file cannot be read.
MclConfig loadMclConfig(const std::string& file);

}  // namespace rgnav
