// ClearanceMap: the shared exact distance transform, with the grid's border counting as blocked.
#include "core/nav/grid/ClearanceMap.h"

#include <algorithm>
#include <cmath>

#include "core/raster/DistanceField.h"

namespace rgnav {

ClearanceMap::ClearanceMap(const OccupancyGrid& grid) : grid_(&grid) {
  const std::vector<float> squared = squaredDistanceToBlocked(grid);
  const int w = grid.width();
  const int h = grid.height();
  distances_.resize(squared.size());
  for (int row = 0; row < h; ++row)
    for (int col = 0; col < w; ++col) {
      // The nearest cell of the ring just outside the grid lies straight across the nearest edge.
      const double toBorder = std::min({col + 1, row + 1, w - col, h - row});
      const std::size_t i = rowMajor({col, row}, w);
      distances_[i] = static_cast<float>(std::min<double>(std::sqrt(double(squared[i])), toBorder) * grid.resolution());
    }
}

}  // namespace rgnav
