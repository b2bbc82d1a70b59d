// rasterize: turns a VectorWorld into the occupancy grid the laser sees. Only obstacles whose
// vertical extent [elevation, elevation + height] contains the laser plane count (thesis 5: the
// SICK laser sits about 0.40 m above the floor), so a table top does not, its legs do. A cell is
// occupied when its centre lies closer than half a cell to an obstacle's footprint, which keeps
// thin and diagonal walls closed for rays. Open doors cut their opening out of the wall.
#pragma once

#include "core/raster/OccupancyGrid.h"
#include "core/sim/world/VectorWorld.h"

namespace rgnav {

constexpr double kLaserPlaneHeight = 0.40;  // m above the floor

// The grid covers world.min..world.max (the floor plan, if any, is the starting layer).
OccupancyGrid rasterize(const VectorWorld& world, double planeHeight = kLaserPlaneHeight);

}  // namespace rgnav
