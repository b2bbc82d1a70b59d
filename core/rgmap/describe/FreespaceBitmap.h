// FreespaceBitmap: the 1-bit freespace map of a region as it is stored and sent (thesis 5.2: "a
// binary occupancy grid map, where for each cell only one bit is stored, indicating whether the
// cell is considered to be free or occupied"; 15 cm cells, "about 200 byte" for 30 m²).
// Layout:
//   - width x height cells of resolutionM metres; cell (col, row) covers
//     [originM.x + col * res, originM.x + (col + 1) * res) x [originM.y + row * res, ...) in the
//     region frame; row 0 is at the bottom (smallest y);
//   - cells are numbered k = row * width + col (row-major, rows not padded to whole bytes); cell k
//     is bit (k % 8) of bytes[k / 8], least significant bit first;
//   - 1 = free, 0 = not free (occupied or never seen); unused bits of the last byte are 0;
//   - bytes.size() == ceil(width * height / 8); an empty map has width = height = 0, no bytes.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rgnav {

struct FreespaceBitmap {
  double resolutionM = 0.0;
  Eigen::Vector2d originM = Eigen::Vector2d::Zero();
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> bytes;

  // A map of the given size with no free cell. Throws InvalidArgumentError for a negative size
  // or a non-positive resolution.
  static FreespaceBitmap allOccupied(double resolutionM, const Eigen::Vector2d& originM, int width, int height);

  void setFree(int col, int row);
  bool isFree(int col, int row) const;  // false outside the map
  // Whether the cell containing `point` (region frame) is free; false outside the map. This is
  // the thesis' quick check "if a given particle lies in the current region".
  bool isFreeAt(const Eigen::Vector2d& point) const;
  std::size_t freeCount() const;
  // The centre of a cell in the region frame.
  Eigen::Vector2d cellCenter(int col, int row) const;
};

bool operator==(const FreespaceBitmap& a, const FreespaceBitmap& b);

}  // namespace rgnav
