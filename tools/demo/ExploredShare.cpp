// The share of the world's reachable free area the map covers (see ExploredShare.h).
#include "tools/demo/ExploredShare.h"

#include <deque>

#include "core/rgmap/describe/FreespaceRaster.h"

namespace rgnav {
namespace {

std::size_t indexOf(const OccupancyGrid& grid, CellIndex c) {
  return static_cast<std::size_t>(c.row) * static_cast<std::size_t>(grid.width()) + static_cast<std::size_t>(c.col);
}

// Row-major, row 0 at the bottom: the free cells 4-connected to `start`.
std::vector<bool> reachableFree(const OccupancyGrid& world, CellIndex start) {
  std::vector<bool> reached(static_cast<std::size_t>(world.width()) * static_cast<std::size_t>(world.height()), false);
  std::deque<CellIndex> open{start};
  reached[indexOf(world, start)] = true;
  while (!open.empty()) {
    const CellIndex c = open.front();
    open.pop_front();
    for (const CellIndex n : {CellIndex{c.col + 1, c.row}, CellIndex{c.col - 1, c.row}, CellIndex{c.col, c.row + 1},
                              CellIndex{c.col, c.row - 1}}) {
      if (world.blocked(n) || reached[indexOf(world, n)]) continue;
      reached[indexOf(world, n)] = true;
      open.push_back(n);
    }
  }
  return reached;
}

}  // namespace

double exploredShare(const OccupancyGrid& world, const WorldPoint& start, const std::vector<RegionView>& regions,
                     const Pose2D& mapToWorld) {
  const std::optional<CellIndex> startCell = world.cellOf(start);
  if (!startCell || world.blocked(*startCell)) return 0.0;
  const std::vector<bool> reachable = reachableFree(world, *startCell);
  const RasterFrame frame{world.resolution(), {world.origin().x, world.origin().y}, world.width(), world.height()};
  std::vector<bool> covered(reachable.size(), false);
  for (const RegionView& region : regions) {
    const std::vector<std::uint8_t> free =
        rasteriseFreespace(region.freespace, compose(mapToWorld, region.summary.frame), frame);
    for (std::size_t i = 0; i < free.size(); ++i) covered[i] = covered[i] || free[i] != 0;
  }
  std::size_t reachableCells = 0, coveredCells = 0;
  for (std::size_t i = 0; i < reachable.size(); ++i) {
    reachableCells += reachable[i];
    coveredCells += reachable[i] && covered[i];
  }
  return double(coveredCells) / double(reachableCells);
}

}  // namespace rgnav
