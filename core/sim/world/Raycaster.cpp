// Raycaster: Amanatides-Woo traversal with distance-field leaps.
#include "core/sim/world/Raycaster.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/common/Errors.h"
#include "core/raster/DistanceField.h"

namespace rgnav {
namespace {

constexpr std::uint8_t kBlocked = 255;
constexpr std::uint8_t kMaxLeap = 254;
// Below this a leap costs more than stepping cell by cell.
constexpr std::uint8_t kMinLeap = 2;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// From a point in a cell whose centre is D cells from the nearest blocked cell centre, a ray can
// advance D - sqrt(2) cells: both the start point and every point of the blocked cell lie
// within sqrt(2)/2 of their centres.
std::uint8_t leapFor(double distance) {
  const double leap = std::floor(distance - std::sqrt(2.0));
  return static_cast<std::uint8_t>(std::clamp(leap, 0.0, double(kMaxLeap)));
}

// Ray parameter (cells) at which the ray p0 + t*d leaves cell i along one axis.
double nextBoundary(int i, double p0, double d, double inverse) {
  if (d > 0.0) return (i + 1 - p0) * inverse;
  if (d < 0.0) return (i - p0) * inverse;
  return std::numeric_limits<double>::infinity();
}

}  // namespace

Raycaster::Raycaster(const OccupancyGrid& grid)
    : width_(grid.width()), height_(grid.height()), resolution_(grid.resolution()), origin_(grid.origin()),
      leap_(grid.cells().size()) {
  const std::vector<float> squared = squaredDistanceToBlocked(grid);
  for (int row = 0; row < height_; ++row) {
    for (int col = 0; col < width_; ++col) {
      const std::size_t i = static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(col);
      if (grid.at({col, row}) != Cell::Free) {
        leap_[i] = kBlocked;
        continue;
      }
      // Outside the grid is blocked too: the nearest outside cell centre.
      const int toBorder = std::min({col + 1, row + 1, width_ - col, height_ - row});
      leap_[i] = leapFor(std::min(std::sqrt(double(squared[i])), double(toBorder)));
    }
  }
}

double Raycaster::castCells(double x, double y, double dx, double dy, double maxCells) const {
  if (!(x >= 0.0 && y >= 0.0 && x < width_ && y < height_)) return 0.0;  // outside, or NaN
  int ix = static_cast<int>(std::floor(x));
  int iy = static_cast<int>(std::floor(y));
  const auto inside = [&] { return ix >= 0 && iy >= 0 && ix < width_ && iy < height_; };
  const auto leapAt = [&] { return leap_[static_cast<std::size_t>(iy) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(ix)]; };
  std::uint8_t leap = leapAt();
  if (leap == kBlocked) return 0.0;

  const double inverseX = 1.0 / dx, inverseY = 1.0 / dy;  // +-inf for an axis-parallel ray
  const int stepX = dx > 0.0 ? 1 : -1, stepY = dy > 0.0 ? 1 : -1;
  const double deltaX = std::abs(inverseX), deltaY = std::abs(inverseY);
  double t = 0.0;
  double boundaryX = nextBoundary(ix, x, dx, inverseX);
  double boundaryY = nextBoundary(iy, y, dy, inverseY);
  for (;;) {
    if (leap >= kMinLeap) {
      t += leap;
      if (t >= maxCells) return kInfinity;
      ix = static_cast<int>(std::floor(x + t * dx));
      iy = static_cast<int>(std::floor(y + t * dy));
      boundaryX = nextBoundary(ix, x, dx, inverseX);
      boundaryY = nextBoundary(iy, y, dy, inverseY);
    } else if (boundaryX < boundaryY) {
      t = boundaryX;
      boundaryX += deltaX;
      ix += stepX;
    } else {
      t = boundaryY;
      boundaryY += deltaY;
      iy += stepY;
    }
    if (t >= maxCells) return kInfinity;
    if (!inside()) return t;
    leap = leapAt();
    if (leap == kBlocked) return t;
  }
}

float Raycaster::cast(WorldPoint from, double angle, double maxRange) const {
  if (!std::isfinite(angle)) throw InvalidArgumentError("Raycaster: beam angle is not finite");
  const double cells = castCells((from.x - origin_.x) / resolution_, (from.y - origin_.y) / resolution_,
                                std::cos(angle), std::sin(angle), maxRange / resolution_);
  return static_cast<float>(cells * resolution_);
}

void Raycaster::scan(const Pose2D& sensor, double startAngle, double increment, double maxRange,
                     std::span<float> ranges) const {
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    ranges[i] = cast({sensor.x, sensor.y}, sensor.theta + startAngle + static_cast<double>(i) * increment, maxRange);
  }
}

}  // namespace rgnav
