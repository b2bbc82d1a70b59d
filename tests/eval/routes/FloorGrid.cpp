// FloorGrid: the global occupancy map, inflated (see the header).
#include "tests/eval/routes/FloorGrid.h"

#include <opencv2/imgproc.hpp>

#include "core/raster/GridMat.h"
#include "core/rgmap/export/OccupancyMap.h"

namespace rgnav {

OccupancyGrid floorGridOf(const RgMapState& state, double resolutionM, double robotRadiusM) {
  OccupancyMapConfig config;
  config.resolutionM = resolutionM;
  OccupancyGrid grid = occupancyMapOf(state, config);
  const cv::Mat cells = cellMat(grid);
  cv::Mat open = cells != static_cast<int>(Cell::Occupied);
  cv::Mat distance;
  cv::distanceTransform(open, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const double clearCells = robotRadiusM / resolutionM;
  for (int r = 0; r < grid.height(); ++r)
    for (int c = 0; c < grid.width(); ++c)
      if (grid.at({c, r}) == Cell::Free && distance.at<float>(r, c) <= clearCells) grid.set({c, r}, Cell::Occupied);
  return grid;
}

}  // namespace rgnav
