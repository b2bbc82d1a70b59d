// Image-to-grid conversion with the row flip.
#include "core/sim/world/ImageGrid.h"

#include "core/common/Errors.h"

namespace rgnav {

OccupancyGrid gridFromImage(const GrayImage& image, double resolution, WorldPoint origin, const GrayToCell& table) {
  OccupancyGrid grid(image.width(), image.height(), resolution, origin);
  for (int row = 0; row < image.height(); ++row) {
    for (int col = 0; col < image.width(); ++col) {
      grid.set(cellOfPixel(col, row, image.height()), table[image.at(col, row)]);
    }
  }
  return grid;
}

void requireSameSize(const GrayImage& image, const std::string& path, const OccupancyGrid& grid) {
  if (image.width() != grid.width() || image.height() != grid.height()) {
    throw InvalidArgumentError(path + ": image is " + std::to_string(image.width()) + "x" +
                               std::to_string(image.height()) + " pixels, the grid " +
                               std::to_string(grid.width()) + "x" + std::to_string(grid.height()) + " cells");
  }
}

}  // namespace rgnav
