// Line-of-sight test between furniture blobs and reachable cells; see Visibility.h.
#include "tests/eval/objects/Visibility.h"

#include <cmath>

namespace rgnav {
namespace {

constexpr int kDirections = 360;
constexpr double kStepCells = 0.25;  // sampling step along a line of sight

// True if the line from the centre of `cell` in direction `angle` reaches a reachable cell before
// a blocked cell of another object or maxCells.
bool seesReachable(const FurnitureTruth& truth, const OccupancyGrid& grid, const std::vector<bool>& reachable,
                   std::size_t cell, double angle, double maxCells) {
  const int blob = truth.blobOfCell[cell];
  const double x0 = static_cast<double>(cell % grid.width()) + 0.5, y0 = static_cast<double>(cell / grid.width()) + 0.5;
  const double dx = std::cos(angle), dy = std::sin(angle);
  for (double t = kStepCells; t <= maxCells; t += kStepCells) {
    const CellIndex c{static_cast<int>(std::floor(x0 + t * dx)), static_cast<int>(std::floor(y0 + t * dy))};
    if (!grid.contains(c)) return false;
    const std::size_t i = static_cast<std::size_t>(c.row) * grid.width() + c.col;
    if (reachable[i]) return true;
    if (grid.at(c) != Cell::Free && truth.blobOfCell[i] != blob) return false;
  }
  return false;
}

bool hasFreeNeighbour(const OccupancyGrid& grid, std::size_t cell) {
  const int col = static_cast<int>(cell % grid.width()), row = static_cast<int>(cell / grid.width());
  for (const CellIndex c : {CellIndex{col + 1, row}, CellIndex{col - 1, row}, CellIndex{col, row + 1},
                            CellIndex{col, row - 1}})
    if (grid.contains(c) && grid.at(c) == Cell::Free) return true;
  return false;
}

bool visible(const FurnitureTruth& truth, const OccupancyGrid& grid, const std::vector<bool>& reachable,
             const FurnitureBlob& blob, double maxCells) {
  for (const std::size_t cell : blob.cells) {
    if (!hasFreeNeighbour(grid, cell)) continue;
    for (int k = 0; k < kDirections; ++k)
      if (seesReachable(truth, grid, reachable, cell, 2.0 * M_PI * k / kDirections, maxCells)) return true;
  }
  return false;
}

}  // namespace

void markInvisible(FurnitureTruth& truth, const OccupancyGrid& grid, const std::vector<bool>& reachable,
                   double maxRangeM) {
  const double maxCells = maxRangeM / grid.resolution();
  for (FurnitureBlob& blob : truth.blobs)
    if (blob.exclusion == Exclusion::kNone && !visible(truth, grid, reachable, blob, maxCells))
      blob.exclusion = Exclusion::kNotVisible;
}

}  // namespace rgnav
