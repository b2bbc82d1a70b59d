// FloorGrid: the whole floor's planning grid for the routes evaluation: the RG map's global
// occupancy map (OccupancyMap.h, every scan at its corrected pose) with occupied cells inflated by
// the robot radius and unknown cells blocked, the grid a planner without regions would plan on.
#pragma once

#include "core/raster/OccupancyGrid.h"
#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

OccupancyGrid floorGridOf(const RgMapState& state, double resolutionM, double robotRadiusM);

}  // namespace rgnav
