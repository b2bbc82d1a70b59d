// LineOfSight: segmentFree() (SegmentVisibility.h) with a fast path through open space, for the
// any-angle searches that check long segments at every expansion. The segment is walked in steps
// as long as the clearance where it is (sphere tracing over the grid's distance transform): from a
// point in cell c, no blocked cell comes nearer than the distance between c's centre and the
// nearest blocked cell's centre less two half-diagonals, nor the grid's edge nearer than it is, so
// the segment is free up to there. Where the clearance drops below a cell, the exact walk of
// segmentFree decides for the whole segment: the answer is always segmentFree's.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

class LineOfSight {
 public:
  // `grid` must outlive this object and not change.
  explicit LineOfSight(const OccupancyGrid& grid);
  // The same as segmentFree(grid, a, b).
  bool free(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;

 private:
  const OccupancyGrid& grid_;
  std::vector<float> clearance_;  // per cell, row-major: the free radius around any point of the cell
};

}  // namespace rgnav
