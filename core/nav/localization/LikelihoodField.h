// LikelihoodField: the precomputed likelihood field of a set of line segments (thesis 5.3: the
// measurement model is evaluated on the line map of the particle's region; Thrun, Burgard, Fox,
// Probabilistic Robotics 2005, 6.4). The segments are drawn into a raster of
// BeamModelConfig::resolutionM, OpenCV's distance transform gives every cell's distance to the
// nearest line. Each cell stores that distance in one byte, in steps of a quarter cell (or of
// sigmaHit / 32 if that is coarser, so that 255 steps reach 8 sigmaHit, where a beam scores as
// random), and a 256-entry table gives log p(z) of a beam ending there (MclConfig.h): a quarter
// of the memory of a float per cell, with the distance rounded to 1.25 cm at 5 cm cells.
// Beam end points outside the raster score like a random measurement (log(zRand / maxRange)).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/nav/localization/MclConfig.h"
#include "core/nav/localization/ScanBeams.h"
#include "core/rgmap/kernel/RgMapViews.h"

namespace rgnav {

class LikelihoodField {
 public:
  // The field of `lines` (all in one frame). No lines: a field that scores every beam as random.
  // Throws ConfigError for a bad configuration.
  LikelihoodField(std::span<const Segment2> lines, const BeamModelConfig& config);

  // log p of one beam end point (in the lines' frame).
  double logLikelihood(const Eigen::Vector2d& point) const;
  // The scan's log-likelihood at `robotPose` (in the lines' frame): the beams' sum times
  // BeamModelConfig::beamWeight.
  double logLikelihood(const Pose2D& robotPose, const ScanBeams& beams) const;
  // The mean log p of points given in the frame of `pose` (robot or observation frame), placed at
  // `pose` in the lines' frame, without beamWeight: how well they fit the lines there. 0 for no points.
  double meanLogLikelihood(const Pose2D& pose, std::span<const Eigen::Vector2d> points) const;

  std::size_t bytes() const;  // memory the field holds
  Eigen::Vector2d origin() const { return origin_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  // The sum of log p of `points` (in the frame of `pose`) placed at `pose`.
  double sumLogLikelihood(const Pose2D& pose, std::span<const Eigen::Vector2d> points) const;

  BeamModelConfig config_;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();  // corner of cell (0, 0)
  int width_ = 0, height_ = 0;
  std::vector<std::uint8_t> steps_;  // per cell, row-major, row 0 at the smallest y: distance steps
  std::array<double, 256> logP_{};   // log p by distance step
  double outside_ = 0.0;             // log p of a point outside the raster
};

}  // namespace rgnav
