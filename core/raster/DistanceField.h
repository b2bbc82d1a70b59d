// squaredDistanceToBlocked: the exact Euclidean distance transform of an occupancy grid, by
// OpenCV's cv::distanceTransform (DIST_L2, DIST_MASK_PRECISE: Felzenszwalb & Huttenlocher,
// "Distance Transforms of Sampled Functions", 2012): the raycaster skips empty space with it,
// the planner keeps its clearance with it.
#pragma once

#include <vector>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// Per cell (row-major), the squared distance in cells between its centre and the centre of the
// nearest blocked cell (Occupied or Unknown; 0 for blocked cells). Cells outside the grid do not
// count here. kNoBlockedCell where the grid has no blocked cell at all.
constexpr float kNoBlockedCell = 1e30f;
std::vector<float> squaredDistanceToBlocked(const OccupancyGrid& grid);

}  // namespace rgnav
