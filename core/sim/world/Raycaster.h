// Raycaster: laser beams through an occupancy grid. Exact grid traversal (Amanatides & Woo, "A
// Fast Voxel Traversal Algorithm for Ray Tracing", 1987) that leaps through empty space by the
// precomputed distance to the nearest blocked cell (DistanceField.h); a leap never passes a
// blocked cell, so the result equals a plain cell-by-cell traversal. Blocked: Occupied, Unknown
// and everything outside the grid (OccupancyGrid::blocked). No allocation per beam or scan.
// Ours, not OpenCV's: cv::LineIterator steps between integer pixel centres and cannot leap; a beam
// starts and ends at real-valued points and needs the exact cell it first enters.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

class Raycaster {
 public:
  // Precomputes the leap table (O(cells)); keeps no reference to `grid`.
  explicit Raycaster(const OccupancyGrid& grid);

  // Metres from `from` along the world-frame direction `angle` to the boundary of the first
  // blocked cell; +inf if there is none within `maxRange`; 0 if `from` is in a blocked cell or
  // outside the grid. A non-finite angle is an InvalidArgumentError.
  float cast(WorldPoint from, double angle, double maxRange) const;

  // ranges[i] = cast(sensor position, sensor.theta + startAngle + i * increment, maxRange).
  void scan(const Pose2D& sensor, double startAngle, double increment, double maxRange, std::span<float> ranges) const;

  double resolution() const { return resolution_; }

 private:
  // In cell units: start (x, y), unit direction (dx, dy); returns cells travelled or +inf.
  double castCells(double x, double y, double dx, double dy, double maxCells) const;

  int width_;
  int height_;
  double resolution_;
  WorldPoint origin_;
  // Per cell: kBlocked, or how many cells a ray may advance from anywhere in it without
  // reaching a blocked cell.
  std::vector<std::uint8_t> leap_;
};

}  // namespace rgnav
