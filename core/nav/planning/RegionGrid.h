// RegionGrid: the planning grid of one region (thesis 5.4): its 2D line map rendered into an
// occupancy grid by Bresenham's line algorithm (OpenCV's 8-connected cv::line), the walls inflated
// by the robot radius (OpenCV's exact Euclidean distance transform), and every cell outside the
// region's freespace blocked, so that paths stay where the robot has seen free floor.
// Deliberate difference: the thesis renders only the line map; without the freespace a path
// could leave the region through a gap of its line map into space never seen.
// The grid is in the region frame; points of planners are in cell units (SegmentVisibility.h).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <vector>

#include "core/raster/OccupancyGrid.h"
#include "core/rgmap/kernel/RgMapViews.h"

namespace rgnav {

struct RegionGrid {
  OccupancyGrid grid;           // region frame
  std::vector<Segment2> walls;  // the line map the grid was rendered from (region frame)

  Eigen::Vector2d toCells(const Eigen::Vector2d& regionPoint) const;
  Eigen::Vector2d toRegion(const Eigen::Vector2d& cellPoint) const;
  // Whether a point (region frame) lies in a free cell.
  bool freeAt(const Eigen::Vector2d& regionPoint) const;
  // The centre of the free cell nearest to `regionPoint` within `maxDistanceM` (region frame) that
  // the straight hop from the point reaches without crossing a wall line, if any; the point itself
  // when its cell is free. For points that lie just inside the inflation around walls (a crossing
  // point at a narrow door, a robot close to a wall): the hop is driven in a straight line.
  // `overWalls`: the hop may cross wall lines (a crossing point the robot drove through, whose
  // door frame the line map may close a little). `usable`, if given: only free cells it accepts
  // count (the point itself too).
  std::optional<Eigen::Vector2d> nearestFree(const Eigen::Vector2d& regionPoint, double maxDistanceM,
                                             bool overWalls = false,
                                             const std::function<bool(CellIndex)>& usable = nullptr) const;
};

// Throws InvalidArgumentError for a non-positive resolution or a negative radius.
RegionGrid buildRegionGrid(const RegionView& region, double resolutionM, double robotRadiusM);

}  // namespace rgnav
