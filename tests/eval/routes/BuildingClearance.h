// BuildingClearance: what the floor plan itself says about a robot of a given radius, the truth
// the routes evaluation checks the maps' paths against: where the robot fits (free cells at least
// its radius from an obstacle, by OpenCV's exact distance transform), the connected pieces of that
// space (8-connected: two places no piece holds together no map could join), and whether a path,
// placed in the floor plan's frame, keeps the robot off the obstacles up to a tolerance for the
// map's own errors.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

class BuildingClearance {
 public:
  // Keeps a reference to `plan`, which must outlive this.
  BuildingClearance(const OccupancyGrid& plan, double radiusM);

  // The piece the robot fits into at cell `c`, -1 where it does not fit.
  int pieceAt(CellIndex c) const { return pieces_.at<int>(c.row, c.col); }
  // Whether every point of `path` (floor-plan frame, sampled every 2.5 cm) lies at least
  // radius - toleranceM from the nearest obstacle of the plan (outside the plan: not).
  bool fits(const std::vector<Eigen::Vector2d>& path, double toleranceM) const;

 private:
  const OccupancyGrid& plan_;
  double radiusM_;
  cv::Mat distance_;  // cells to the nearest non-free cell, per cell
  cv::Mat pieces_;
};

}  // namespace rgnav
