// groundTruthOf: the ground truth a vector world carries: each free cell whose centre lies in
// a room polygon (even-odd rule; the first polygon wins where they overlap) belongs to that
// room, and every door's opening is a door line with the rooms on either side.
#pragma once

#include "core/raster/OccupancyGrid.h"
#include "core/sim/GroundTruth.h"
#include "core/sim/world/VectorWorld.h"

namespace rgnav {

constexpr double kDoorProbeBeyondWall = 1.0;  // m past the wall face to look for a door's rooms

// `grid` is rasterize(world) (or any grid of the world's geometry).
GroundTruth groundTruthOf(const VectorWorld& world, const OccupancyGrid& grid);

}  // namespace rgnav
