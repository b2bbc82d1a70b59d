// GridDrawing: the cells whose centres fall into a world interval, then the per-cell test.
#include "core/sim/scenarios/GridDrawing.h"

#include <algorithm>
#include <cmath>

namespace rgnav {

namespace {

struct IndexRange {
  int first;
  int last;  // inclusive; empty if last < first
};

// Indices i in [0, count) whose cell centre origin + (i + 0.5) res lies in [lo, hi].
IndexRange centresWithin(double lo, double hi, double origin, double res, int count) {
  const int first = static_cast<int>(std::ceil((lo - origin) / res - 0.5));
  const int last = static_cast<int>(std::floor((hi - origin) / res - 0.5));
  return {std::max(first, 0), std::min(last, count - 1)};
}

}  // namespace

void fillRect(OccupancyGrid& grid, const WorldRect& rect, Cell value) {
  const IndexRange cols = centresWithin(rect.minX, rect.maxX, grid.origin().x, grid.resolution(), grid.width());
  const IndexRange rows = centresWithin(rect.minY, rect.maxY, grid.origin().y, grid.resolution(), grid.height());
  for (int row = rows.first; row <= rows.last; ++row) {
    for (int col = cols.first; col <= cols.last; ++col) {
      grid.set({col, row}, value);
    }
  }
}

void fillDisk(OccupancyGrid& grid, WorldPoint centre, double radius, Cell value) {
  const IndexRange cols = centresWithin(centre.x - radius, centre.x + radius, grid.origin().x,
                                        grid.resolution(), grid.width());
  const IndexRange rows = centresWithin(centre.y - radius, centre.y + radius, grid.origin().y,
                                        grid.resolution(), grid.height());
  for (int row = rows.first; row <= rows.last; ++row) {
    for (int col = cols.first; col <= cols.last; ++col) {
      const WorldPoint p = grid.center({col, row});
      if (std::hypot(p.x - centre.x, p.y - centre.y) <= radius) {
        grid.set({col, row}, value);
      }
    }
  }
}

}  // namespace rgnav
