// OdometryNoiseModel: makes the odometry a simulated robot reports from its true motion. Each
// true increment is decomposed into rot1 / trans / rot2 and perturbed with zero-mean Gaussian
// noise of the variances of the odometry motion model (Thrun, Burgard, Fox, Probabilistic
// Robotics, 2005, Table 5.6, sample_motion_model_odometry):
//   var(rot1)  = alpha1 rot1^2 + alpha2 trans^2
//   var(trans) = alpha3 trans^2 + alpha4 (rot1^2 + rot2^2)
//   var(rot2)  = alpha1 rot2^2 + alpha2 trans^2
// used here in the generative direction (odometry = truth + noise). Before the noise a
// systematic drift is applied (Borenstein & Feng 1996, "UMBmark", systematic odometry errors):
// a scale error on translation (trans * (1 + translationScaleError)) and a heading bias
// proportional to the distance driven (rotationBiasPerMetre * |trans|, half added to rot1 and
// half to rot2). Seeded std::mt19937_64; the same seed gives the same odometry.
#pragma once

#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/OdometryMotion.h"

namespace rgnav {

struct OdometryNoiseConfig {
  double alpha1 = 0.01;    // rad^2/rad^2: rotation noise from rotation
  double alpha2 = 0.0005;  // rad^2/m^2: rotation noise from translation
  double alpha3 = 0.01;    // m^2/m^2: translation noise from translation
  double alpha4 = 0.0001;  // m^2/rad^2: translation noise from rotation
  double translationScaleError = 0.0;  // dimensionless; +0.01 reports 1 % too much distance
  double rotationBiasPerMetre = 0.0;   // rad/m; heading error added per metre driven
};

// Throws ConfigError for a negative or non-finite alpha, a non-finite drift term or a scale
// error <= -1.
void validate(const OdometryNoiseConfig& config);

class OdometryNoiseModel {
 public:
  // Throws ConfigError for a bad configuration.
  OdometryNoiseModel(const OdometryNoiseConfig& config, std::uint64_t seed);

  // The odometry pose after the robot moved from `trueFrom` to `trueTo`, given the odometry pose
  // reported at `trueFrom`.
  Pose2D advance(const Pose2D& odometry, const Pose2D& trueFrom, const Pose2D& trueTo);

  // The odometry pose sequence of a true pose sequence; the first odometry pose is
  // `odometryStart` (odometry frames start anywhere).
  std::vector<Pose2D> odometryPoses(std::span<const Pose2D> truePoses, const Pose2D& odometryStart);

 private:
  // The odometry motion reported for a true motion: drift, then noise.
  OdometryMotion sample(const OdometryMotion& truth);
  double gaussian(double variance);

  OdometryNoiseConfig config_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace rgnav
