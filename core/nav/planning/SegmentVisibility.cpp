// SegmentVisibility: the cell walk of a segment through an OccupancyGrid (see the header).
#include "core/nav/planning/SegmentVisibility.h"

#include <cmath>
#include <limits>

namespace rgnav {

namespace {

bool blockedAt(const OccupancyGrid& grid, int col, int row) { return grid.blocked(CellIndex{col, row}); }

// The first cell index along one axis of a segment starting at coordinate `p` going in direction
// `step` (-1, 0, +1): on a grid line, the cell on the side the segment goes to.
int firstCell(double p, int step) {
  const double f = std::floor(p);
  return (step < 0 && f == p) ? static_cast<int>(f) - 1 : static_cast<int>(f);
}

// A passage through grid vertex (x, y): the two cells the segment does not enter must not both be
// blocked (a squeeze between diagonal obstacles).
bool squeezedAt(const OccupancyGrid& grid, int x, int y) {
  return (blockedAt(grid, x - 1, y - 1) && blockedAt(grid, x, y)) ||
         (blockedAt(grid, x, y - 1) && blockedAt(grid, x - 1, y));
}

// A segment on the grid line `line` of one axis, from `from` to `to` along the other axis.
// `along(k, m)` maps (line coordinate, cell or vertex coordinate along) to (col, row).
template <class Along>
bool onGridLineFree(const OccupancyGrid& grid, int line, double from, double to, Along along) {
  const double lo = std::min(from, to), hi = std::max(from, to);
  const int first = static_cast<int>(std::floor(lo));
  const int last = static_cast<int>(std::ceil(hi)) - 1;
  for (int m = first; m <= last; ++m) {
    const auto [c0, r0] = along(line - 1, m);
    const auto [c1, r1] = along(line, m);
    if (blockedAt(grid, c0, r0) && blockedAt(grid, c1, r1)) return false;
    if (m > first) {
      const auto [vx, vy] = along(line, m);
      if (squeezedAt(grid, vx, vy)) return false;
    }
  }
  return true;
}

}  // namespace

bool segmentFree(const OccupancyGrid& grid, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  if (!std::isfinite(dx) || !std::isfinite(dy)) return false;
  if (dx == 0.0 && dy == 0.0) {
    const int c = static_cast<int>(std::floor(a.x())), r = static_cast<int>(std::floor(a.y()));
    const bool onX = std::floor(a.x()) == a.x(), onY = std::floor(a.y()) == a.y();
    for (int i = onX ? -1 : 0; i <= 0; ++i)
      for (int j = onY ? -1 : 0; j <= 0; ++j)
        if (!blockedAt(grid, c + i, r + j)) return true;
    return false;
  }
  if (dx == 0.0 && std::floor(a.x()) == a.x())
    return onGridLineFree(grid, static_cast<int>(a.x()), a.y(), b.y(),
                          [](int k, int m) { return std::pair{k, m}; });
  if (dy == 0.0 && std::floor(a.y()) == a.y())
    return onGridLineFree(grid, static_cast<int>(a.y()), a.x(), b.x(),
                          [](int k, int m) { return std::pair{m, k}; });

  const int stepX = dx > 0 ? 1 : (dx < 0 ? -1 : 0);
  const int stepY = dy > 0 ? 1 : (dy < 0 ? -1 : 0);
  int col = firstCell(a.x(), stepX), row = firstCell(a.y(), stepY);
  if (blockedAt(grid, col, row)) return false;
  constexpr double kNever = std::numeric_limits<double>::infinity();
  for (;;) {
    const double tx = stepX == 0 ? kNever : ((stepX > 0 ? col + 1 : col) - a.x()) / dx;
    const double ty = stepY == 0 ? kNever : ((stepY > 0 ? row + 1 : row) - a.y()) / dy;
    if (tx >= 1.0 && ty >= 1.0) return true;
    if (tx < ty) {
      col += stepX;
    } else if (ty < tx) {
      row += stepY;
    } else {
      if (squeezedAt(grid, stepX > 0 ? col + 1 : col, stepY > 0 ? row + 1 : row)) return false;
      col += stepX;
      row += stepY;
    }
    if (blockedAt(grid, col, row)) return false;
  }
}

}  // namespace rgnav
