// exploredShare: how much of the floor the navigating demo's map covers: the share of the world's
// reachable free area (the simulator's world grid: its free cells 4-connected to the robot's start
// cell, so neither the inside of furniture nor space outside the building counts) that lies in a
// free cell of some region's freespace (thesis 5.2's 1-bit map, 15 cm cells), each region placed
// into the world with mapToWorld ⊕ its frame (rasteriseFreespace, nearest-cell sampling at the
// world cells' centres). A 15 cm cell straddling a wall is not free, so a map of the whole floor
// stays somewhat below 1. The demo program reads the world file for this, as an evaluation does;
// no module of the robot does.
#pragma once

#include <vector>

#include "core/common/Pose2D.h"
#include "core/raster/OccupancyGrid.h"
#include "core/rgmap/kernel/RgMapViews.h"

namespace rgnav {

// 0 if the start cell is not free (or outside the world).
double exploredShare(const OccupancyGrid& world, const WorldPoint& start, const std::vector<RegionView>& regions,
                     const Pose2D& mapToWorld);

}  // namespace rgnav
