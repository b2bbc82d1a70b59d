// freeRunM: how far free space extends from a point in one direction on an occupancy grid,
// walked in half-cell steps until the first blocked cell (outside the grid is blocked). The
// door evaluation measures with it how wide the space beside a ground-truth door line is.
#pragma once

#include <Eigen/Core>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// 0 if `from` itself is blocked; at most maxM. `direction` must be a unit vector.
double freeRunM(const OccupancyGrid& grid, const Eigen::Vector2d& from, const Eigen::Vector2d& direction, double maxM);

}  // namespace rgnav
