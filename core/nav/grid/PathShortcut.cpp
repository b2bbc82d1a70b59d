// PathShortcut: greedy farthest-visible-cell selection with sampled clearance checks.
#include "core/nav/grid/PathShortcut.h"

#include <algorithm>
#include <cmath>

namespace rgnav {

namespace {

// Whether the segment from path[i] to path[j] keeps, at samples at most half a cell apart, the
// clearance the cell path had at the same fraction of the way (capped at `desired`).
bool segmentClear(const ClearanceMap& map, std::span<const CellIndex> path, std::size_t i,
                  std::size_t j, double desired) {
  const CellIndex a = path[i], b = path[j];
  const double length = std::hypot(double(b.col - a.col), double(b.row - a.row));
  const int samples = std::max(1, static_cast<int>(std::ceil(length * 2.0)));
  const OccupancyGrid& grid = map.grid();
  const WorldPoint pa = grid.center(a);
  const WorldPoint pb = grid.center(b);
  for (int k = 0; k <= samples; ++k) {
    const double t = double(k) / samples;
    const auto along = i + static_cast<std::size_t>(std::lround(t * double(j - i)));
    const double required = std::min(desired, map.at(path[along]));
    const auto cell = grid.cellOf({pa.x + t * (pb.x - pa.x), pa.y + t * (pb.y - pa.y)});
    if (!cell || map.at(*cell) < required) {
      return false;
    }
  }
  return true;
}

}  // namespace

std::vector<CellIndex> shortcutPath(const ClearanceMap& map, std::span<const CellIndex> path,
                                    double desiredClearance) {
  std::vector<CellIndex> kept;
  if (path.empty()) {
    return kept;
  }
  kept.push_back(path.front());
  std::size_t i = 0;
  while (i + 1 < path.size()) {
    std::size_t best = i + 1;
    for (std::size_t j = i + 2; j < path.size() && segmentClear(map, path, i, j, desiredClearance); ++j) {
      best = j;
    }
    kept.push_back(path[best]);
    i = best;
  }
  return kept;
}

}  // namespace rgnav
