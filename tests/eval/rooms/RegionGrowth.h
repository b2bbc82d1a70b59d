// growIntoUnclaimed: the regions of an RG Map on a floor plan of finer cells, for scoring them as
// a segmentation of it (RegionPixels.h). A region's 1-bit freespace
// (15 cm cells, FreespaceRaster.h) leaves out the strip along its walls: a cell that holds the
// wall is occupied, though most of it may be free floor. Each region grows, by a breadth-first
// wavefront over 8-neighbours, into the map's free cells that no region claims, at most
// maxGrowCells steps from its own cells; walls stop it. Cells two regions claim stay claimed by
// both (regions are not a partition: each holds what it saw, thesis 2.1.1). The benchmark's own
// segmentations end the same way: a wavefront growth of the segments over the map's free cells.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace rgnav {

struct RegionRaster {
  std::int64_t regionId = 0;
  std::vector<std::uint8_t> claimed;  // one value per map cell, non-zero where the region holds it
};

// Grows every raster of a width x height map (row-major) in place; `mapFree` is non-zero on the
// map's free cells. Throws InvalidArgumentError if a raster or mapFree does not have
// width * height values, or for negative sizes or a negative maxGrowCells.
void growIntoUnclaimed(std::span<RegionRaster> regions, std::span<const std::uint8_t> mapFree, int width, int height,
                       int maxGrowCells);

}  // namespace rgnav
