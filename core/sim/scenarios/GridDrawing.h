// GridDrawing: rasterises axis-aligned rectangles and discs into an OccupancyGrid (a cell takes
// the value if its centre lies inside the shape, boundary included), for generated worlds and
// test worlds.
#pragma once

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct WorldRect {
  double minX = 0.0;
  double minY = 0.0;
  double maxX = 0.0;
  double maxY = 0.0;
};

// Cells outside the grid are skipped.
void fillRect(OccupancyGrid& grid, const WorldRect& rect, Cell value);
void fillDisk(OccupancyGrid& grid, WorldPoint centre, double radius, Cell value);

}  // namespace rgnav
