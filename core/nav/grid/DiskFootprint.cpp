// DiskFootprint: visits the cells under the disk's bounding box and measures each blocked one.
#include "core/nav/grid/DiskFootprint.h"

#include <algorithm>
#include <cmath>

namespace rgnav {

namespace {

// Distance along one axis from `p` to the interval [lo, hi] (0 inside).
double gap(double p, double lo, double hi) { return std::max({lo - p, 0.0, p - hi}); }

}  // namespace

bool diskCollides(const OccupancyGrid& grid, WorldPoint centre, double radius) {
  const double res = grid.resolution();
  const WorldPoint o = grid.origin();
  const int col0 = static_cast<int>(std::floor((centre.x - radius - o.x) / res));
  const int col1 = static_cast<int>(std::floor((centre.x + radius - o.x) / res));
  const int row0 = static_cast<int>(std::floor((centre.y - radius - o.y) / res));
  const int row1 = static_cast<int>(std::floor((centre.y + radius - o.y) / res));
  for (int row = row0; row <= row1; ++row) {
    const double dy = gap(centre.y, o.y + row * res, o.y + (row + 1) * res);
    for (int col = col0; col <= col1; ++col) {
      if (!grid.blocked({col, row})) {
        continue;
      }
      const double dx = gap(centre.x, o.x + col * res, o.x + (col + 1) * res);
      if (dx * dx + dy * dy < radius * radius) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace rgnav
