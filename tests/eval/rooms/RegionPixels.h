// regionPixels: the regions of a final RG Map as segments of the floor plan for the room scoring
// (RoomScoring.h): each region's 1-bit freespace (15 cm cells, region frame) placed into the world
// frame with its frame pose and mapToWorld, sampled at the floor plan's pixel centres
// (rasteriseFreespace, thesis 2.3.2: a global metric map extracted on demand) and kept only on the
// world's free pixels: the pixels a segmentation of the furnished floor plan can label, as the
// benchmark's segmentations do (a 15 cm cell straddling a wall is free only on its free side).
// Each region then grows up to growM over the free pixels no region claims (growIntoUnclaimed,
// RegionGrowth.h: the strip along walls that 15 cm cells holding the wall leave out), as the
// benchmark's segmentations end with a wavefront growth over the free pixels. Last, each region
// takes the holes up to maxHoleM2 that its pixels enclose and no other region holds
// (fillEnclosedHoles, RegionHoles.h: furniture standing free in a room, which the ground-truth
// rooms include).
#pragma once

#include <vector>

#include "core/common/Pose2D.h"
#include "core/raster/OccupancyGrid.h"
#include "tests/eval/rooms/FinalMap.h"
#include "tests/eval/rooms/RoomScoring.h"

namespace rgnav {

// One segment per region, ID = region ID, pixel indices row * width + col of `world` (row 0 at
// the bottom, as GroundTruth::labels). Throws InvalidArgumentError for a negative or non-finite
// maxHoleM2 or a negative growM.
std::vector<SegmentPixels> regionPixels(const FinalMap& map, const Pose2D& mapToWorld, const OccupancyGrid& world,
                                        double growM, double maxHoleM2);

}  // namespace rgnav
