// Test helper: random grids for the planners' tests (cells blocked independently with a given
// share, 1 m cells at the origin) and random free cells and points in them.
#pragma once

#include <Eigen/Core>
#include <random>

#include "core/raster/OccupancyGrid.h"

namespace rgnav::testing {

OccupancyGrid randomGrid(std::mt19937& rng, int width, int height, double blockedShare);
inline OccupancyGrid randomGrid(std::mt19937& rng, int size, double blockedShare) {
  return randomGrid(rng, size, size, blockedShare);
}
// The grid must have a free cell.
CellIndex randomFreeCell(std::mt19937& rng, const OccupancyGrid& grid);
// A point (cell units) anywhere inside a free cell.
Eigen::Vector2d randomFreePoint(std::mt19937& rng, const OccupancyGrid& grid);

}  // namespace rgnav::testing
