// ReferenceMap: what a scan is registered against: the points and normals of one or more
// keyframes placed in a common frame (the recent keyframes in the map frame for local
// registration, a submap in its anchor's frame for loop closing), rasterised into a PointGrid and
// its LikelihoodPyramid.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/slam/LikelihoodPyramid.h"
#include "core/slam/PointGrid.h"

namespace rgnav {

// The pyramid levels a search with this translational half width needs (top cell > window).
int pyramidLevelsFor(double maxTranslation, double resolution);

class ReferenceMap {
 public:
  ReferenceMap(const GridConfig& grid, int pyramidLevels);

  // Starts a new reference; add scans, then build().
  void clear();
  // Adds the points and normals (sensor frame; equal sizes) of a scan taken at `pose`.
  void add(std::span<const Eigen::Vector2f> points, std::span<const Eigen::Vector2f> normals, const Pose2D& pose);
  // Rasterises what was added.
  void build();

  bool empty() const { return points_.empty(); }
  const std::vector<Eigen::Vector2d>& points() const { return points_; }
  const std::vector<Eigen::Vector2d>& normals() const { return normals_; }  // zero: no normal
  const PointGrid& grid() const { return grid_; }
  const LikelihoodPyramid& pyramid() const { return pyramid_; }

 private:
  int pyramidLevels_;
  std::vector<Eigen::Vector2d> points_;
  std::vector<Eigen::Vector2d> normals_;
  PointGrid grid_;
  LikelihoodPyramid pyramid_;
};

}  // namespace rgnav
