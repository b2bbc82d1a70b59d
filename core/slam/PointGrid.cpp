// Disc stamping of the reference points into the distance / nearest-index / likelihood grid.
#include "core/slam/PointGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/Errors.h"

namespace rgnav {

namespace {
constexpr double kTableSteps = 64.0;  // squared-distance table entries per resolution^2
}

PointGrid::PointGrid(const GridConfig& config)
    : resolution_(config.resolution),
      inverseResolution_(1.0 / config.resolution),
      sigma_(config.sigma),
      nearestRadius_(config.nearestRadius),
      stampRadius_(std::max(config.nearestRadius, 3.0 * config.sigma)) {
  if (!(resolution_ > 0.0) || !(sigma_ > 0.0) || !(nearestRadius_ > 0.0))
    throw ConfigError("slam: grid resolution, sigma and nearestRadius must be positive");
  const double maxCells2 = (stampRadius_ * inverseResolution_ + 1.0) * (stampRadius_ * inverseResolution_ + 1.0) * 2.0;
  likelihoodTable_.resize(static_cast<std::size_t>(maxCells2 * kTableSteps) + 2);
  for (std::size_t i = 0; i < likelihoodTable_.size(); ++i) {
    const double d2 = static_cast<double>(i) / kTableSteps * resolution_ * resolution_;
    likelihoodTable_[i] = static_cast<float>(std::exp(-d2 / (2.0 * sigma_ * sigma_)));
  }
}

void PointGrid::build(std::span<const Eigen::Vector2d> points) {
  if (points.empty()) {
    width_ = height_ = 0;
    return;
  }
  Eigen::Vector2d lo = points.front(), hi = points.front();
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  origin_ = lo - Eigen::Vector2d::Constant(stampRadius_ + resolution_);
  width_ = static_cast<int>(std::ceil((hi.x() - origin_.x() + stampRadius_ + resolution_) * inverseResolution_));
  height_ = static_cast<int>(std::ceil((hi.y() - origin_.y() + stampRadius_ + resolution_) * inverseResolution_));
  const std::size_t cells = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  distance2_.assign(cells, std::numeric_limits<float>::infinity());
  nearest_.assign(cells, -1);
  likelihood_.assign(cells, 0);

  const int radiusCells = static_cast<int>(std::ceil(stampRadius_ * inverseResolution_));
  const double stamp2 = stampRadius_ * stampRadius_;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d& p = points[i];
    const Eigen::Vector2i c = cellOf(p);
    for (int cy = c.y() - radiusCells; cy <= c.y() + radiusCells; ++cy) {
      const double dy = origin_.y() + (cy + 0.5) * resolution_ - p.y();
      for (int cx = c.x() - radiusCells; cx <= c.x() + radiusCells; ++cx) {
        const double dx = origin_.x() + (cx + 0.5) * resolution_ - p.x();
        const double d2 = dx * dx + dy * dy;
        if (d2 > stamp2) continue;
        const std::size_t k = index(cx, cy);
        if (d2 < distance2_[k]) {
          distance2_[k] = static_cast<float>(d2);
          nearest_[k] = static_cast<int>(i);
        }
      }
    }
  }
  const double nearest2 = nearestRadius_ * nearestRadius_;
  const double tableScale = kTableSteps * inverseResolution_ * inverseResolution_;
  for (std::size_t k = 0; k < cells; ++k) {
    const double d2 = distance2_[k];
    if (!std::isfinite(d2)) continue;
    likelihood_[k] = static_cast<std::uint8_t>(std::lround(255.0 * likelihoodTable_[static_cast<std::size_t>(d2 * tableScale)]));
    if (d2 > nearest2) nearest_[k] = -1;
  }
}

}  // namespace rgnav
