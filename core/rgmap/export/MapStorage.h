// mapStorage: how many bytes an RG Map takes against an occupancy grid of the same extent (thesis
// 5.2: a region's 1-bit freespace map of 30 m² takes about 200 bytes where a probabilistic grid
// map would take more than 5300). Counted as a compact binary encoding would store them:
//   - RG Map: per region its frame (3 x float32 = 12 bytes), its freespace bitmap
//     (FreespaceBitmap::bytes) and its line map (4 x float32 = 16 bytes per segment); per gateway
//     8 bytes (2 x float32) per gateway point and per crossing point. IDs, names, class
//     probabilities and the descriptions' scalar features are left out: they are the same few
//     bytes per region or gateway whatever the map's extent;
//   - occupancy grid: one byte per cell (as the exported PGM, OccupancyMap.h) over mapExtent
//     (MapExtent.h) at gridResolutionM.
// Deliberate difference: the thesis compares with 4-byte probabilities at the same 15 cm; we
// compare with the 5 cm 1-byte grid users actually get from a ROS map_server map.
#pragma once

#include <cstddef>

#include "core/rgmap/export/RgMapSnapshot.h"

namespace rgnav {

struct MapStorage {
  std::size_t rgMapBytes = 0;
  std::size_t occupancyGridBytes = 0;  // 0 for an empty map
};

// Throws InvalidArgumentError for a non-positive or non-finite resolution.
MapStorage mapStorage(const RgMapSnapshot& map, double gridResolutionM = 0.05);

}  // namespace rgnav
