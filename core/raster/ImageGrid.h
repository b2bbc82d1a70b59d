// Image <-> occupancy grid geometry: image row 0 is the top, grid row 0 the bottom
// (OccupancyGrid.h), so rows flip; one pixel is one cell. Shared by the floor-plan and
// map_server loaders, the ground-truth loader and the map_server writer.
#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// The cell each of the 256 gray values becomes.
using GrayToCell = std::array<Cell, 256>;

// The grid cell of image pixel (col, row) of an image `imageHeight` rows high.
inline CellIndex cellOfPixel(int col, int row, int imageHeight) { return {col, imageHeight - 1 - row}; }

// A grid of the size of `image` (CV_8UC1); `origin` is the world position of the image's
// bottom-left corner.
OccupancyGrid gridFromImage(const cv::Mat& image, double resolution, WorldPoint origin, const GrayToCell& table);

// An 8-bit gray image of the grid (CV_8UC1, row 0 at the top), each cell painted `gray(cell)`.
template <typename GrayOf>
cv::Mat imageFromGrid(const OccupancyGrid& grid, GrayOf gray) {
  cv::Mat image(grid.height(), grid.width(), CV_8UC1);
  for (int row = 0; row < grid.height(); ++row) {
    auto* pixels = image.ptr<std::uint8_t>(grid.height() - 1 - row);
    for (int col = 0; col < grid.width(); ++col) pixels[col] = gray(grid.at({col, row}));
  }
  return image;
}

// Throws InvalidArgumentError naming `path` if the image and the grid differ in size.
void requireSameSize(const cv::Mat& image, const std::string& path, const OccupancyGrid& grid);

}  // namespace rgnav
