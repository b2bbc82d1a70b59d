// cellMat: an OccupancyGrid's cells as an 8-bit cv::Mat (one Cell value per element, grid row 0
// in Mat row 0, i.e. upside down against image files), so that OpenCV's operations run on grids.
#pragma once

#include <opencv2/core.hpp>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// A copy; changing it does not change the grid.
inline cv::Mat cellMat(const OccupancyGrid& grid) {
  static_assert(sizeof(Cell) == 1);
  return cv::Mat(grid.height(), grid.width(), CV_8U, const_cast<Cell*>(grid.cells().data())).clone();
}

}  // namespace rgnav
