// PointCloud: the scan points of a whole tour for the point-based object paths (circles, small
// clusters), thinned to one point per 1 cm square (a robot standing still repeats its scans).
// Each point also comes "pushed" half a grid cell further along its beam: the simulated laser
// measures to the boundary of the first occupied cell, so a pushed point lies inside the cell
// that stopped the beam (range noise is 1 cm, the push 2.5 cm).
#pragma once

#include <Eigen/Core>
#include <unordered_set>
#include <vector>

#include "core/common/SensorData.h"

namespace rgnav {

struct CloudPoint {
  Eigen::Vector2d surface;  // as measured
  Eigen::Vector2d pushed;   // half a cell deeper along the beam
};

class PointCloud {
 public:
  explicit PointCloud(double cellSizeM, double thinningM = 0.01);

  // Adds the valid points of `scan`, taken at its sensorPose.
  void add(const LaserScan& scan);
  const std::vector<CloudPoint>& points() const { return points_; }

 private:
  double push_;
  double thinning_;
  std::unordered_set<std::uint64_t> occupied_;  // thinning squares already holding a point
  std::vector<CloudPoint> points_;
};

}  // namespace rgnav
