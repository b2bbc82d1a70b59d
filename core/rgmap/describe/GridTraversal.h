// traverseCells: the cells of a square lattice that a straight segment passes through, in order
// (Amanatides & Woo, "A Fast Voxel Traversal Algorithm for Ray Tracing", 1987). Used to mark the
// cells a laser beam crossed as free and to find the cells a gateway line runs through.
// Coordinates are in cell units: cell (i, j) covers [i, i + 1) x [j, j + 1). The walk is
// 4-connected: where the segment passes exactly through a lattice corner it steps in y first, so
// the cells of a line have no diagonal gaps.
// Ours, not OpenCV's: cv::LineIterator walks pixel centres (Bresenham, 4- or 8-connected), so it
// skips cells a beam clips at a corner and works on integer end points; this walk needs every cell
// a real-valued segment touches.
#pragma once

#include <cmath>
#include <limits>

namespace rgnav {

struct LatticeCell {
  int i = 0;
  int j = 0;
  friend bool operator==(const LatticeCell&, const LatticeCell&) = default;
};

// Calls visit(i, j) for every cell the segment (x0, y0)-(x1, y1) passes through before the cell
// that contains (x1, y1), and returns that last cell. Nothing is visited when both ends lie in
// one cell. The coordinates must be finite and small enough for int cell indices.
template <class Visit>
LatticeCell traverseCells(double x0, double y0, double x1, double y1, Visit&& visit) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  int i = static_cast<int>(std::floor(x0)), j = static_cast<int>(std::floor(y0));
  const int iEnd = static_cast<int>(std::floor(x1)), jEnd = static_cast<int>(std::floor(y1));
  const double dx = x1 - x0, dy = y1 - y0;
  const int stepI = dx > 0.0 ? 1 : -1, stepJ = dy > 0.0 ? 1 : -1;
  // Parameter (0 at the start, 1 at the end) per cell width, and where the next border is crossed.
  const double deltaX = dx != 0.0 ? 1.0 / std::fabs(dx) : kNever;
  const double deltaY = dy != 0.0 ? 1.0 / std::fabs(dy) : kNever;
  double nextX = dx > 0.0 ? (i + 1 - x0) * deltaX : dx < 0.0 ? (x0 - i) * deltaX : kNever;
  double nextY = dy > 0.0 ? (j + 1 - y0) * deltaY : dy < 0.0 ? (y0 - j) * deltaY : kNever;
  while (i != iEnd || j != jEnd) {
    visit(i, j);
    // Counting down to the end cell (not comparing parameters with 1) makes the walk end there
    // whatever the rounding.
    if (i != iEnd && (j == jEnd || nextX < nextY)) {
      nextX += deltaX;
      i += stepI;
    } else {
      nextY += deltaY;
      j += stepJ;
    }
  }
  return {i, j};
}

}  // namespace rgnav
