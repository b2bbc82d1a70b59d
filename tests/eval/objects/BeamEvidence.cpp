// Hit and pass counts of laser beams per grid cell; see BeamEvidence.h.
#include "tests/eval/objects/BeamEvidence.h"

#include <algorithm>
#include <cmath>

namespace rgnav {

BeamEvidence::BeamEvidence(const OccupancyGrid& grid)
    : width_(grid.width()),
      height_(grid.height()),
      resolution_(grid.resolution()),
      origin_(grid.origin()),
      hits_(grid.cells().size(), 0),
      passes_(grid.cells().size(), 0) {}

std::int64_t BeamEvidence::cellAt(double x, double y) const {
  const int col = static_cast<int>(std::floor((x - origin_.x) / resolution_));
  const int row = static_cast<int>(std::floor((y - origin_.y) / resolution_));
  if (col < 0 || row < 0 || col >= width_ || row >= height_) return -1;
  return static_cast<std::int64_t>(row) * width_ + col;
}

void BeamEvidence::add(const LaserScan& scan) {
  const Pose2D& s = scan.sensorPose;
  const double step = 0.5 * resolution_;
  for (std::size_t beam = 0; beam < scan.ranges.size(); ++beam) {
    const double range = scan.ranges[beam];
    if (!std::isfinite(range)) continue;
    const double angle = s.theta + scan.startAngle + static_cast<double>(beam) * scan.angleIncrement;
    const double dx = std::cos(angle), dy = std::sin(angle);
    std::int64_t last = -1;
    for (double t = 0.0; t < range - resolution_; t += step) {
      const std::int64_t cell = cellAt(s.x + t * dx, s.y + t * dy);
      if (cell < 0) break;
      if (cell != last) ++passes_[static_cast<std::size_t>(cell)];
      last = cell;
    }
    const double end = range + 0.5 * resolution_;
    if (const std::int64_t cell = cellAt(s.x + end * dx, s.y + end * dy); cell >= 0)
      ++hits_[static_cast<std::size_t>(cell)];
  }
}

std::vector<std::size_t> BeamEvidence::growIntoUnobserved(std::vector<std::size_t> cells, int steps) const {
  std::vector<std::size_t> front = cells;
  for (int step = 0; step < steps && !front.empty(); ++step) {
    std::vector<std::size_t> next;
    for (const std::size_t cell : front) {
      const int col = static_cast<int>(cell % static_cast<std::size_t>(width_));
      const int row = static_cast<int>(cell / static_cast<std::size_t>(width_));
      for (const auto& [c, r] : {std::pair(col + 1, row), std::pair(col - 1, row), std::pair(col, row + 1),
                                 std::pair(col, row - 1)}) {
        if (c < 0 || r < 0 || c >= width_ || r >= height_) continue;
        const auto n = static_cast<std::size_t>(r) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c);
        if (unobserved(n) && std::find(cells.begin(), cells.end(), n) == cells.end()) {
          cells.push_back(n);
          next.push_back(n);
        }
      }
    }
    front = std::move(next);
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

}  // namespace rgnav
