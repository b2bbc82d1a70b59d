// Beam traversal marking of seen-free cells; see FreeSpace.h.
#include "tests/eval/objects/FreeSpace.h"

#include <cmath>

namespace rgnav {

FreeSpace::FreeSpace(const OccupancyGrid& grid)
    : width_(grid.width()),
      height_(grid.height()),
      resolution_(grid.resolution()),
      origin_(grid.origin()),
      seen_(grid.cells().size(), 0) {}

void FreeSpace::add(const LaserScan& scan) {
  const Pose2D& s = scan.sensorPose;
  const double step = 0.5 * resolution_;
  for (std::size_t beam = 0; beam < scan.ranges.size(); ++beam) {
    const double range = scan.ranges[beam];
    if (!std::isfinite(range)) continue;
    const double angle = s.theta + scan.startAngle + static_cast<double>(beam) * scan.angleIncrement;
    const double dx = std::cos(angle), dy = std::sin(angle);
    for (double t = 0.0; t < range - resolution_; t += step) {
      const int col = static_cast<int>(std::floor((s.x + t * dx - origin_.x) / resolution_));
      const int row = static_cast<int>(std::floor((s.y + t * dy - origin_.y) / resolution_));
      if (col < 0 || row < 0 || col >= width_ || row >= height_) break;
      seen_[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(col)] = 1;
    }
  }
}

}  // namespace rgnav
