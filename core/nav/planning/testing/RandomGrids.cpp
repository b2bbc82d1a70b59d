// Test helper: random grids (see RandomGrids.h).
#include "core/nav/planning/testing/RandomGrids.h"

namespace rgnav::testing {

OccupancyGrid randomGrid(std::mt19937& rng, int width, int height, double blockedShare) {
  OccupancyGrid grid(width, height, 1.0);
  std::bernoulli_distribution blocked(blockedShare);
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c)
      if (blocked(rng)) grid.set({c, r}, Cell::Occupied);
  return grid;
}

CellIndex randomFreeCell(std::mt19937& rng, const OccupancyGrid& grid) {
  std::uniform_int_distribution<int> col(0, grid.width() - 1), row(0, grid.height() - 1);
  for (;;) {
    const CellIndex c{col(rng), row(rng)};
    if (!grid.blocked(c)) return c;
  }
}

Eigen::Vector2d randomFreePoint(std::mt19937& rng, const OccupancyGrid& grid) {
  std::uniform_real_distribution<double> x(0.0, grid.width()), y(0.0, grid.height());
  for (;;) {
    const Eigen::Vector2d p(x(rng), y(rng));
    if (!grid.blocked({static_cast<int>(p.x()), static_cast<int>(p.y())})) return p;
  }
}

}  // namespace rgnav::testing
