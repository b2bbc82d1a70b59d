// LineOfSight: sphere tracing over the distance transform, falling back to segmentFree (see the
// header).
#include "core/nav/planning/LineOfSight.h"

#include <algorithm>
#include <cmath>

#include "core/nav/planning/SegmentVisibility.h"
#include "core/raster/DistanceField.h"

namespace rgnav {

namespace {

constexpr double kMinStep = 1.0;  // cells; below this clearance the exact walk is cheaper
constexpr double kSqrt2 = 1.4142135623730951;
// Kept off every computed clearance: far above the rounding of the steps, far below the least
// distance by which a segment between half-cell lattice points can miss a cell's corner.
constexpr double kMargin = 1e-3;

}  // namespace

LineOfSight::LineOfSight(const OccupancyGrid& grid) : grid_(grid) {
  const std::vector<float> squared = squaredDistanceToBlocked(grid);
  clearance_.resize(squared.size());
  for (std::size_t i = 0; i < squared.size(); ++i)
    clearance_[i] = squared[i] == kNoBlockedCell ? 1e30f : static_cast<float>(std::sqrt(double(squared[i])) - kSqrt2 - kMargin);
}

bool LineOfSight::free(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  const Eigen::Vector2d delta = b - a;
  const double length = delta.norm();
  if (!(length > 0.0) || !std::isfinite(length)) return segmentFree(grid_, a, b);
  const Eigen::Vector2d direction = delta / length;
  double travelled = 0.0;
  for (;;) {
    const Eigen::Vector2d x = a + direction * travelled;
    const int col = static_cast<int>(std::floor(x.x())), row = static_cast<int>(std::floor(x.y()));
    if (!grid_.contains({col, row}) || grid_.blocked({col, row})) return segmentFree(grid_, a, b);
    const double edge = std::min({x.x(), x.y(), grid_.width() - x.x(), grid_.height() - x.y()});
    const double step = std::min(edge, double(clearance_[static_cast<std::size_t>(row) * grid_.width() + col]));
    if (step < kMinStep) return segmentFree(grid_, a, b);
    travelled += step;
    if (travelled >= length) return true;
  }
}

}  // namespace rgnav
