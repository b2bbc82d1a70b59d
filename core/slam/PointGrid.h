// PointGrid: a reference point set rasterised once, for two look-ups: the likelihood of a cell
// (a Gaussian of the distance from the cell centre to the nearest point, quantised to 0..255, the
// "rasterized cost table" of Olson 2009, real-time correlative scan matching) and the index of
// that nearest point (the correspondence search of point-to-line ICP in constant time, instead
// of the k-d tree or the scan-order search of Censi 2008). Built by stamping a disc around each
// point; the buffers are reused across builds.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/slam/SlamConfig.h"

namespace rgnav {

class PointGrid {
 public:
  // Throws ConfigError for a non-positive resolution, sigma or radius.
  explicit PointGrid(const GridConfig& config);

  // Replaces the content with `points` (any frame); the grid covers them plus the stamp radius.
  void build(std::span<const Eigen::Vector2d> points);

  double resolution() const { return resolution_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // The cell containing p (possibly outside the grid).
  Eigen::Vector2i cellOf(const Eigen::Vector2d& p) const {
    return {static_cast<int>(std::floor((p.x() - origin_.x()) * inverseResolution_)),
            static_cast<int>(std::floor((p.y() - origin_.y()) * inverseResolution_))};
  }
  // The centre of cell (0, 0) is origin() + resolution() / 2 in both axes.
  const Eigen::Vector2d& origin() const { return origin_; }

  bool contains(int cx, int cy) const { return cx >= 0 && cy >= 0 && cx < width_ && cy < height_; }
  // 0 outside the grid.
  std::uint8_t likelihood(int cx, int cy) const {
    return contains(cx, cy) ? likelihood_[index(cx, cy)] : std::uint8_t{0};
  }
  // Row-major, width() * height().
  std::span<const std::uint8_t> likelihoods() const { return likelihood_; }
  // The index (into the points given to build) of the point nearest to the cell centre, -1 if
  // no point lies within nearestRadius or the cell is outside the grid.
  int nearest(int cx, int cy) const { return contains(cx, cy) ? nearest_[index(cx, cy)] : -1; }

 private:
  std::size_t index(int cx, int cy) const {
    return static_cast<std::size_t>(cy) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(cx);
  }

  double resolution_;
  double inverseResolution_;
  double sigma_;
  double nearestRadius_;
  double stampRadius_;
  std::vector<float> likelihoodTable_;  // by squared distance in units of resolution^2 / kTableSteps
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  int width_ = 0;
  int height_ = 0;
  std::vector<float> distance2_;
  std::vector<int> nearest_;
  std::vector<std::uint8_t> likelihood_;
};

}  // namespace rgnav
