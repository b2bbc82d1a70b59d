// Fusing obstacle grids into one (see ObstacleFusion.h).
#include "core/nav/avoidance/ObstacleFusion.h"

namespace rgnav {

namespace {

// The Occupied cells of one layer of every grid, on the geometry of the first grid's cells.
OccupancyGrid fuseLayer(std::span<const ObstacleGrid> grids, OccupancyGrid ObstacleGrid::*layer) {
  if (grids.empty() || grids.front().cells.cells().empty())
    throw InvalidArgumentError("fuseObstacles: no obstacle grid to fuse");
  const OccupancyGrid& first = grids.front().cells;
  OccupancyGrid out(first.width(), first.height(), first.resolution(), first.origin(), Cell::Free);
  for (const ObstacleGrid& grid : grids) {
    const OccupancyGrid& cells = grid.*layer;
    for (int row = 0; row < cells.height(); ++row)
      for (int col = 0; col < cells.width(); ++col) {
        if (cells.at({col, row}) != Cell::Occupied) continue;
        if (const auto c = out.cellOf(cells.center({col, row}))) out.set(*c, Cell::Occupied);
      }
  }
  return out;
}

}  // namespace

OccupancyGrid fuseObstacles(std::span<const ObstacleGrid> grids) { return fuseLayer(grids, &ObstacleGrid::cells); }

OccupancyGrid fuseMovingObstacles(std::span<const ObstacleGrid> grids) { return fuseLayer(grids, &ObstacleGrid::moving); }

}  // namespace rgnav
