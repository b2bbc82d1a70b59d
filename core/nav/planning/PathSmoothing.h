// PathSmoothing: the path optimisation of thesis 5.4 (figure 5.8 left) for polylines in cell
// units (SegmentVisibility.h). Greedy string pulling drops intermediate points while the shortcut
// stays segmentFree; then every bend at a cell centre moves onto one corner of its cell, or two
// along one side, where that shortens the path most with every segment still free (the Euclidean
// shortest path bends at obstacle corners), and both repeat until nothing changes. With a per-cell cost field (wall costs), a
// shortcut is taken only if its cost is not higher than the points it drops, and bends stay put.
// Every change shortens the path (or with costs, cheapens it), never lengthens it; the first and
// last points never move.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// `cellCost`: empty, or per cell (row-major) the extra cost per cell of path length.
void smoothPath(const OccupancyGrid& grid, const std::vector<float>& cellCost, std::vector<Eigen::Vector2d>& points);

}  // namespace rgnav
