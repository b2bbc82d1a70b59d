// loadFloorPlan: the benchmark's free/occupied threshold applied to a gray image.
#include "core/sim/world/FloorPlan.h"

#include "core/raster/ImageFile.h"
#include "core/raster/ImageGrid.h"

namespace rgnav {

OccupancyGrid floorPlanFromImage(const cv::Mat& image, double resolution, WorldPoint origin) {
  GrayToCell table{};
  for (int gray = 0; gray < 256; ++gray) {
    table[gray] = isFloorPlanFree(static_cast<std::uint8_t>(gray)) ? Cell::Free : Cell::Occupied;
  }
  return gridFromImage(image, resolution, origin, table);
}

OccupancyGrid loadFloorPlan(const std::string& imagePath, double resolution, WorldPoint origin) {
  if (!(resolution > 0.0)) throw InvalidArgumentError(imagePath + ": resolution must be positive");
  return floorPlanFromImage(readGrayImage(imagePath), resolution, origin);
}

}  // namespace rgnav
