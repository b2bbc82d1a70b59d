// MclConfig: the parameters of the region Monte Carlo localization (RegionMcl.h) and of its parts:
// the likelihood-field beam model (LikelihoodField.h), the odometry motion model
// (OdometrySampler.h), KLD-sampling (KldSampling.h) and the hand-over of particles at gateways.
// YAML: config/modules/localization.yaml (MclConfigYaml.h); the defaults here are the shipped values.
#pragma once

#include <cstddef>

namespace rgnav {

// The likelihood-field model of a range beam (Thrun, Burgard, Fox, Probabilistic Robotics 2005,
// 6.4, Table 6.3): p(z) = zHit * N(d; 0, sigmaHit^2) + zRand / maxRange, d = distance from the
// beam's end point to the nearest line of the map. Beams without a return are skipped.
struct BeamModelConfig {
  double resolutionM = 0.05;   // m: field cell size
  double sigmaHitM = 0.08;     // m
  double zHit = 0.9;
  double zRand = 0.1;
  double maxRangeM = 30.0;     // beams at or beyond this (or without a return) are skipped
  double marginM = 1.0;        // the field reaches this far beyond the lines' bounding box
  // A region's field also holds the lines of every region whose freespace shares at least this
  // many (15 cm) cells with its own (LocalizationMap.h).
  std::size_t overlapMinCells = 45;
  // Beams used per update, evenly spread over the scan. beams and beamWeight (and minParticles)
  // were tuned on the first half of the Intel keyframes ("rgctl eval localization",
  // docs/EVALUATION.md): 120 beams at 0.1 weigh a scan as 60 at 0.2 did, with less noise.
  std::size_t beams = 120;
  // The log-likelihood of a scan is the beams' sum times this (< 1: beams are not independent;
  // Thrun et al. 6.3.4 "beam correlation").
  double beamWeight = 0.1;
};

// The four-alpha odometry motion model (Thrun et al. 5.4, Table 5.6).
struct MotionModelConfig {
  double alpha1 = 0.05;   // rad^2/rad^2: rotation noise from rotation
  double alpha2 = 0.01;   // rad^2/m^2: rotation noise from translation
  double alpha3 = 0.05;   // m^2/m^2: translation noise from translation
  double alpha4 = 0.005;  // m^2/rad^2: translation noise from rotation
};

// KLD-sampling (Fox 2003): the particle count bound for a histogram of bins over (x, y, theta).
struct KldConfig {
  std::size_t minParticles = 1000;  // fewer leave the estimate noisy (Intel: 0.062 m at 100, 0.049 m at 1000)
  std::size_t maxParticles = 5000;
  double epsilon = 0.05;  // bound on the KL divergence
  double upperQuantile = 2.326;  // z_(1-delta), delta = 0.01
  double binXyM = 0.2;
  double binThetaRad = 0.1745;  // 10 degrees
};

struct MclConfig {
  BeamModelConfig beam;
  MotionModelConfig motion;
  KldConfig kld;
  // A filter update runs only after the odometry moved this far (or turned this much) since the
  // last one (Thrun et al. 8.3.5: updating a standing robot collapses the particle set).
  double updateMinTravelM = 0.05;
  double updateMinTurnRad = 0.05;
  // Resample only when the effective sample size falls below this share of the particle count.
  double resampleBelowEss = 0.5;
  // Particles within this distance of a gateway's centre are handed over to the region on the
  // other side once they are nearer to that side's crossing point (RegionMcl.h).
  double handoverRadiusM = 3.0;
  // The estimate confirms a gateway traversal once it lies this far beyond the gateway (thesis
  // 5.3: "a reasonable distance behind the gateway").
  double traversalConfirmM = 0.5;
  // Particles within this distance and angle of a cluster's seed join its cluster (ParticleClusters.h).
  double clusterRadiusM = 0.5;
  double clusterAngleRad = 0.5;
};

// Throws ConfigError naming the first bad field (non-positive sizes, probabilities outside [0, 1],
// minParticles > maxParticles, ...).
void validate(const MclConfig& config);

}  // namespace rgnav
