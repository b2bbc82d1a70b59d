// RegionRecognition: global localization by recognising the region the robot is in (issue 28;
// the thesis 5.3 names it as future work: "different features from the region description like
// size, number of connected gateways, binary gridmap for freespace ... an action history can be
// utilized"). The observation (LocalObservation.h: the recent scans at their odometry poses, in
// the frame of the newest) is compared with every mapped region:
//   1. descriptor: descriptorDistance (RegionDescriptor.h) of the observation's and the region's
//      features; it ranks regions and enters each candidate's score with descriptorWeight;
//   2. rotations: the observation's line main directions aligned with the region's (every pair,
//      each up to quarter turns: walls of indoor rooms meet at right angles, and an undirected
//      direction leaves a half turn open); without main directions on either side, a sweep in
//      rotationSweepStepRad;
//   3. translations: for each rotation a correlation of the observation with the region's data on
//      the 15 cm raster of the freespace bitmap (OpenCV matchTemplate, TM_CCORR): the beam end
//      points against the region's likelihood field (LocalizationMap::field: its own and its
//      neighbours' lines, so beams through open doors count), mapped to [0, 1], minus
//      freeOnWallWeight times the share of observed free cells that fall onto the region's walls
//      (cells whose field value exceeds wallLevel). Only translations that put the robot on or
//      next to the region's freespace (within robotFreeMarginM) count: the robot is in that
//      region. The peaksPerRotation best of them, at least peakSeparationM apart, are kept;
//   4. refinement: each peak is refined by coordinate descent on the field's mean log-likelihood
//      of refinePoints end points (steps halved from refineStepM / refineStepRad three times);
//      that mean (the fit per point, as PoseEstimate::fitPerBeam) is the candidate's fit.
// A candidate's score is fit - descriptorWeight * descriptor distance. Candidates come out best
// first, at most candidatesPerRegion per region. The descriptor weighs little (0.1: a region whose
// shape clearly contradicts the view loses a few tenths per point): a view of a few metres covers
// a room only partly and reaches through doors into its neighbours, so area and axes separate
// regions far less sharply than the fit of the end points does.
// Cost: per region the field raster is sampled once (cached); per recognition and region a few
// matchTemplate calls (one per rotation and template) on rasters of the region plus
// templateRadiusM on each side; tens of milliseconds for a floor of thirty regions.
#pragma once

#include <map>
#include <opencv2/core.hpp>
#include <vector>

#include "core/nav/localization/LocalizationMap.h"
#include "core/nav/localization/RegionDescriptor.h"

namespace rgnav {

struct RecognitionConfig {
  double cellM = 0.15;              // the correlation raster (the freespace bitmap's 15 cm)
  double templateRadiusM = 8.0;     // observation data farther from the robot is left out of the correlation
  double freeOnWallWeight = 0.5;
  double wallLevel = 0.3;           // field value in [0, 1] above which a cell is wall
  double robotFreeMarginM = 0.3;
  double rotationSweepStepRad = 10.0 * M_PI / 180.0;
  std::size_t peaksPerRotation = 3;
  double peakSeparationM = 1.0;
  std::size_t refinePoints = 300;
  double refineStepM = 0.1;
  double refineStepRad = 2.0 * M_PI / 180.0;
  std::size_t candidatesPerRegion = 3;
  double descriptorWeight = 0.1;
  DescriptorWeights descriptor;
};

struct PoseCandidate {
  RegionId region;
  Pose2D regionPose;  // the robot in the region's frame
  Pose2D mapPose;     // the same in the map frame
  double fit = 0.0;   // mean log-likelihood per end point on the region's field
  double descriptorDistance = 0.0;
  double score = 0.0;  // fit - descriptorWeight * descriptorDistance
};

class RegionRecognizer {
 public:
  // `map` (its fields, of cell size beams.resolutionM) must outlive the recognizer; `regions` and
  // `gateways` are the views the map was made from (their descriptors are computed here). Throws
  // ConfigError for a bad configuration.
  RegionRecognizer(const RecognitionConfig& config, const BeamModelConfig& beams, const LocalizationMap& map,
                   const std::vector<RegionView>& regions, const std::vector<GatewayView>& gateways);

  // All candidates, best score first. Empty if the observation has no end point.
  std::vector<PoseCandidate> recognize(const LocalObservation& observation) const;

  // The candidate the observation makes of a pose found otherwise (e.g. the filter's estimate),
  // scored as the recognizer's own. NotAvailableError for a region not in the map.
  PoseCandidate candidateAt(RegionId region, const Pose2D& regionPose, const LocalObservation& observation) const;

  // The mean log-likelihood per point of `points` (local frame) with the robot at `regionPose` in
  // `region` (the fit a candidate is ranked by).
  double fit(RegionId region, const Pose2D& regionPose, const std::vector<Eigen::Vector2d>& points) const;

  const std::map<RegionId, RegionDescriptor>& descriptors() const { return descriptors_; }

 private:
  // The region's field sampled on the correlation raster (padded by templateRadiusM), its wall
  // cells and where the robot may stand; built on first use.
  struct RegionRaster {
    Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // corner of cell (0, 0), region frame
    cv::Mat score;     // CV_32F in [0, 1], row = y cell
    cv::Mat wall;      // CV_32F 0 / 1
    cv::Mat standing;  // CV_8U 1 where the robot may stand
  };
  const RegionRaster& raster(RegionId region) const;
  std::vector<PoseCandidate> searchRegion(RegionId region, const LocalObservation& observation,
                                          const std::vector<double>& rotations,
                                          const std::vector<Eigen::Vector2d>& refinePoints) const;
  Pose2D refine(RegionId region, Pose2D pose, const std::vector<Eigen::Vector2d>& points) const;

  RecognitionConfig config_;
  double fieldResolutionM_;
  const LocalizationMap& map_;
  std::map<RegionId, RegionDescriptor> descriptors_;
  mutable std::map<RegionId, RegionRaster> rasters_;
};

}  // namespace rgnav
