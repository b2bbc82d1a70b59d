// OccupancyGrid: a world as a grid of free / occupied / unknown cells with a
// resolution and an origin. World frame: x to the right, y up, metres. Cell (col, row) covers
// [origin.x + col*res, origin.x + (col+1)*res) x [origin.y + row*res, origin.y + (row+1)*res);
// row 0 is at the bottom (image loaders flip: image row 0 is the top; ImageGrid.h). The simulator's
// worlds, the exported global map and the ground truth are such grids; GridMat.h hands the cells
// to OpenCV.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/common/Errors.h"

namespace rgnav {

enum class Cell : std::uint8_t { Free = 0, Occupied = 1, Unknown = 2 };

struct CellIndex {
  int col = 0;
  int row = 0;
  friend bool operator==(const CellIndex&, const CellIndex&) = default;
};

struct WorldPoint {
  double x = 0.0;
  double y = 0.0;
};

class OccupancyGrid {
 public:
  OccupancyGrid() = default;
  // Throws InvalidArgumentError for a non-positive size or resolution.
  OccupancyGrid(int width, int height, double resolution, WorldPoint origin = {}, Cell fill = Cell::Free)
      : width_(width), height_(height), resolution_(resolution), origin_(origin) {
    if (width <= 0 || height <= 0 || !(resolution > 0.0))
      throw InvalidArgumentError("OccupancyGrid: size and resolution must be positive");
    cells_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill);
  }

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return resolution_; }
  WorldPoint origin() const { return origin_; }

  bool contains(CellIndex c) const { return c.col >= 0 && c.row >= 0 && c.col < width_ && c.row < height_; }
  Cell at(CellIndex c) const { return cells_[index(c)]; }
  void set(CellIndex c, Cell value) { cells_[index(c)] = value; }
  // Outside the grid counts as occupied: nothing leaves the world.
  bool blocked(CellIndex c) const { return !contains(c) || at(c) != Cell::Free; }

  std::optional<CellIndex> cellOf(WorldPoint p) const {
    const CellIndex c{static_cast<int>(std::floor((p.x - origin_.x) / resolution_)),
                      static_cast<int>(std::floor((p.y - origin_.y) / resolution_))};
    if (!contains(c)) return std::nullopt;
    return c;
  }
  WorldPoint center(CellIndex c) const {
    return {origin_.x + (c.col + 0.5) * resolution_, origin_.y + (c.row + 0.5) * resolution_};
  }

  const std::vector<Cell>& cells() const { return cells_; }

 private:
  std::size_t index(CellIndex c) const {
    return static_cast<std::size_t>(c.row) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c.col);
  }

  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.05;
  WorldPoint origin_;
  std::vector<Cell> cells_;
};

}  // namespace rgnav
