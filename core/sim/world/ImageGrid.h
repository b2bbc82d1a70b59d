// Image <-> occupancy grid geometry: image row 0 is the top, grid row 0 the bottom
// (OccupancyGrid.h), so rows flip; one pixel is one cell. Shared by the floor-plan and
// map_server loaders and the ground-truth loader.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "core/sim/OccupancyGrid.h"
#include "core/sim/world/Image.h"

namespace rgnav {

// The cell each of the 256 gray values becomes.
using GrayToCell = std::array<Cell, 256>;

// The grid cell of image pixel (col, row) of an image `imageHeight` rows high.
inline CellIndex cellOfPixel(int col, int row, int imageHeight) { return {col, imageHeight - 1 - row}; }

// A grid of the image's size; `origin` is the world position of the image's bottom-left corner.
OccupancyGrid gridFromImage(const GrayImage& image, double resolution, WorldPoint origin, const GrayToCell& table);

// Throws InvalidArgumentError naming `path` if the image and the grid differ in size.
void requireSameSize(const GrayImage& image, const std::string& path, const OccupancyGrid& grid);

}  // namespace rgnav
