// ClearanceMap: for every cell of an OccupancyGrid, the Euclidean distance (metres) from its
// centre to the centre of the nearest blocked cell (occupied, unknown, or the ring of cells just
// outside the grid), from the exact distance transform of DistanceField.h.
#pragma once

#include <vector>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// Offset of cell `c` in row-major per-cell arrays of a grid `width` cells wide (the layout of
// OccupancyGrid::cells()).
inline std::size_t rowMajor(CellIndex c, int width) {
  return static_cast<std::size_t>(c.row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(c.col);
}

class ClearanceMap {
 public:
  // Keeps a reference to `grid`, which must outlive the map.
  explicit ClearanceMap(const OccupancyGrid& grid);
  ClearanceMap(OccupancyGrid&&) = delete;

  const OccupancyGrid& grid() const { return *grid_; }
  // 0 for blocked cells; `c` must lie inside the grid.
  double at(CellIndex c) const { return distances_[rowMajor(c, grid_->width())]; }

 private:
  const OccupancyGrid* grid_;
  std::vector<float> distances_;
};

}  // namespace rgnav
