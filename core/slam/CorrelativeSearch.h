// correlativeSearch: the multi-resolution correlative scan matcher of Olson 2009 ("Real-time
// correlative scan matching"), searched exactly by branch and bound over the likelihood pyramid as
// in Hess et al. 2016 (Cartographer): the pose in a window around a guess that maximises the mean
// likelihood of the scan's points. Differences: no prior term inside the search (the odometry
// prior enters in the refinement, ScanRefinement), and the score is an integer sum of
// quantised likelihoods.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>

#include "core/common/Pose2D.h"
#include "core/slam/LikelihoodPyramid.h"
#include "core/slam/PointGrid.h"

namespace rgnav {

struct SearchWindow {
  double translation = 0.0;  // m, half width in x and y
  double rotation = 0.0;     // rad, half width
};

struct CorrelativeMatch {
  Pose2D pose;         // of the sensor in the grid's frame
  double score = 0.0;  // mean likelihood of the points, [0, 1]
};

// The angular step of the search lattice: the angle that moves the point at the 90th percentile
// of the ranges by one grid cell (Hess et al. 2016 use the farthest point; the farthest few
// points move more, which the point-to-line refinement absorbs, and far fewer angles are needed).
double angularStep(std::span<const Eigen::Vector2f> query, double resolution);

// `query`: points in the sensor frame; `guess`: centre of the window in the grid's frame. The
// pyramid must have been built from `grid`. Returns the best pose of the window's lattice
// (steps: one grid cell, angularStep) if its score reaches minScore, else nullopt (also for an
// empty query or grid).
std::optional<CorrelativeMatch> correlativeSearch(const PointGrid& grid, const LikelihoodPyramid& pyramid,
                                                  std::span<const Eigen::Vector2f> query, const Pose2D& guess,
                                                  const SearchWindow& window, double minScore);

}  // namespace rgnav
