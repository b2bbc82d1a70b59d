// occupancyMapOf / exportOccupancyMap: the global metric map of an RG Map on demand (thesis 2.3.2:
// global metric maps are not kept in RG Maps, "but they can be extracted easily on demand"): an
// occupancy grid in the map frame built from every aligned scan the kernel holds
// (RgMapState::scans) at its current corrected pose, so it follows every pose the SLAM revised.
// Cells are counted as a region's freespace counts them (RegionFreespace.h, here with no gateway
// cutting any beam and the grid in the map frame): a beam marks the cells it passes as free and
// the cell it ends in on an obstacle as hit; a cell is free once passed at least freePerHit
// times per hit, occupied if hit more often than that, unknown if no beam reached it; beams
// without return are free up to noReturnFreeRangeM. The grid is cropped to the cells beams
// reached and lies on the map frame's lattice (cell (i, j) covers [i * res, (i + 1) * res) x ...),
// so exports of the same map at different times line up.
// Cost: one grid walk per beam; memory 8 bytes per cell while counting (a 40 x 40 m map at 5 cm:
// 5 MB), at most kMaxOccupancyCells cells per side.
#pragma once

#include <string>

#include "core/raster/OccupancyGrid.h"
#include "core/rgmap/export/MapServerWriter.h"
#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

struct OccupancyMapConfig {
  double resolutionM = 0.05;
  double noReturnFreeRangeM = 3.0;
  double freePerHit = 4.0;
};

inline constexpr int kMaxOccupancyCells = 8000;

// Throws ConfigError for a non-positive or non-finite resolution or a negative range or ratio,
// NotAvailableError for a state without scans, InvalidArgumentError if the scans reach farther
// apart than kMaxOccupancyCells cells.
OccupancyGrid occupancyMapOf(const RgMapState& state, const OccupancyMapConfig& config = {});

// occupancyMapOf, written as <dir>/<name>.pgm and <dir>/<name>.yaml (MapServerWriter.h).
MapServerFiles exportOccupancyMap(const std::string& dir, const std::string& name, const RgMapState& state,
                                  const OccupancyMapConfig& config = {});

}  // namespace rgnav
