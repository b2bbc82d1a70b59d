// Fusing obstacle grids into one (see ObstacleFusion.h).
#include "core/nav/avoidance/ObstacleFusion.h"

namespace rgnav {

OccupancyGrid fuseObstacles(std::span<const ObstacleGrid> grids) {
  if (grids.empty() || grids.front().cells.cells().empty())
    throw InvalidArgumentError("fuseObstacles: no obstacle grid to fuse");
  const OccupancyGrid& first = grids.front().cells;
  OccupancyGrid out(first.width(), first.height(), first.resolution(), first.origin(), Cell::Free);
  for (const ObstacleGrid& grid : grids) {
    const OccupancyGrid& cells = grid.cells;
    for (int row = 0; row < cells.height(); ++row)
      for (int col = 0; col < cells.width(); ++col) {
        if (cells.at({col, row}) != Cell::Occupied) continue;
        if (const auto c = out.cellOf(cells.center({col, row}))) out.set(*c, Cell::Occupied);
      }
  }
  return out;
}

}  // namespace rgnav
