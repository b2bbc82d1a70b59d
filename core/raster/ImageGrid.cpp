// Image-to-grid conversion with the row flip.
#include "core/raster/ImageGrid.h"

#include "core/common/Errors.h"

namespace rgnav {

OccupancyGrid gridFromImage(const cv::Mat& image, double resolution, WorldPoint origin, const GrayToCell& table) {
  if (image.type() != CV_8UC1) throw InvalidArgumentError("gridFromImage: the image must be 8-bit gray");
  OccupancyGrid grid(image.cols, image.rows, resolution, origin);
  for (int row = 0; row < image.rows; ++row) {
    const auto* pixels = image.ptr<std::uint8_t>(row);
    for (int col = 0; col < image.cols; ++col) grid.set(cellOfPixel(col, row, image.rows), table[pixels[col]]);
  }
  return grid;
}

void requireSameSize(const cv::Mat& image, const std::string& path, const OccupancyGrid& grid) {
  if (image.cols != grid.width() || image.rows != grid.height()) {
    throw InvalidArgumentError(path + ": image is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                               " pixels, the grid " + std::to_string(grid.width()) + "x" +
                               std::to_string(grid.height()) + " cells");
  }
}

}  // namespace rgnav
