// fillEnclosedHoles: a region of an RG Map on a floor plan also covers what stands inside it. A
// region's freespace (RegionPixels.h) has a hole wherever furniture stands free in the room (a
// table, a cabinet in the middle, a pillar): the laser saw around it, not under it. A room is the
// floor with its furniture (the ground-truth rooms of the floor plans include the furniture's
// pixels, floorplans/SOURCES.md), so each region takes the holes its own pixels enclose: the
// 4-connected sets of pixels it does not hold that do not reach the border of its bounding box,
// are at most maxHoleCells large (furniture, not a block of rooms that a corridor runs around)
// and hold no pixel another region holds. Furniture against a wall leaves no hole (the wall
// joins it to the outside) and stays unclaimed.
#pragma once

#include <cstddef>
#include <span>

#include "tests/eval/rooms/RegionGrowth.h"

namespace rgnav {

// In place, on width x height rasters (row-major). Throws InvalidArgumentError if a raster does
// not have width * height values or a size is negative.
void fillEnclosedHoles(std::span<RegionRaster> regions, int width, int height, std::size_t maxHoleCells);

}  // namespace rgnav
