// fuseObstacles: the obstacle grids of all sensors (laser, stereo, ...) as one grid of obstacle
// cells for the swept-footprint check: a cell is an obstacle if any grid marks it Occupied; seen
// free and never seen both count as free (the robot drives into space no sensor has seen, as it
// must without a map). Thesis 5.5.3 fuses laser and stereo per cell with a Kalman-like weighted
// mean; here each sensor's own grid has done that filtering and an obstacle of any sensor wins.
#pragma once

#include <span>

#include "core/nav/avoidance/ObstacleGrid.h"

namespace rgnav {

// On the geometry of the first grid (the others' obstacle cells are mapped by their centres).
// InvalidArgumentError for no grids or an empty first grid.
OccupancyGrid fuseObstacles(std::span<const ObstacleGrid> grids);
// The same for the moving obstacles (grids that do not tell them add none).
OccupancyGrid fuseMovingObstacles(std::span<const ObstacleGrid> grids);

}  // namespace rgnav
