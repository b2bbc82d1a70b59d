// Detection footprints in the map grid; see Detection.h.
#include "tests/eval/objects/Detection.h"

#include <algorithm>
#include <cmath>

namespace rgnav {

std::string kindName(DetectionKind kind) {
  switch (kind) {
    case DetectionKind::kRectangle: return "rectangle";
    case DetectionKind::kCircle: return "circle";
    case DetectionKind::kCluster: return "cluster";
  }
  return "?";
}

std::vector<std::size_t> rasterize(const Polygon& outline, const std::vector<Eigen::Vector2d>& anchors,
                                   const OccupancyGrid& grid) {
  std::vector<std::size_t> cells;
  const auto add = [&](CellIndex c) {
    if (grid.contains(c)) cells.push_back(static_cast<std::size_t>(c.row) * grid.width() + c.col);
  };
  const auto cellOf = [&](const Eigen::Vector2d& p) {
    return CellIndex{static_cast<int>(std::floor((p.x() - grid.origin().x) / grid.resolution())),
                     static_cast<int>(std::floor((p.y() - grid.origin().y) / grid.resolution()))};
  };
  if (!outline.empty()) {
    Eigen::Vector2d lo = outline.front(), hi = lo;
    for (const auto& v : outline) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    const CellIndex a = cellOf(lo), b = cellOf(hi);
    for (int row = a.row; row <= b.row; ++row)
      for (int col = a.col; col <= b.col; ++col) {
        const WorldPoint c = grid.center({col, row});
        if (insideConvex(outline, {c.x, c.y}, 0.0)) add({col, row});
      }
  }
  for (const auto& p : anchors) add(cellOf(p));
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

}  // namespace rgnav
