// DiskFootprint: whether a round robot of a given radius, centred at a point, overlaps a blocked
// cell of an OccupancyGrid (occupied, unknown or outside the grid). The exact disk-versus-square
// test (closest point of each cell square to the disk centre); touching is not overlapping.
#pragma once

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

bool diskCollides(const OccupancyGrid& grid, WorldPoint centre, double radius);

}  // namespace rgnav
