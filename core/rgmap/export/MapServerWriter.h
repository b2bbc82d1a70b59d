// writeMapServerMap: an occupancy grid as a ROS map_server map, the format ROS tools and our own
// loader (MapServerYaml.h) read: <name>.pgm (binary P5, core/raster/ImageFile.h; free 254, occupied 0, unknown 205,
// as map_server's map_saver writes them; image row 0 is the grid's top row) and <name>.yaml:
//   image: <name>.pgm
//   resolution: <m per pixel>
//   origin: [x, y, 0]      # the map-frame position of the bottom-left pixel's corner
//   negate: 0
//   occupied_thresh: 0.65
//   free_thresh: 0.196
// With these thresholds map_server reads 254 as free, 0 as occupied and 205 as unknown.
#pragma once

#include <cstdint>
#include <string>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct MapServerFiles {
  std::string yamlPath;
  std::string imagePath;
};

inline constexpr std::uint8_t kMapFreeGray = 254, kMapOccupiedGray = 0, kMapUnknownGray = 205;

// Writes <dir>/<name>.pgm, then <dir>/<name>.yaml, each atomically. Throws InvalidArgumentError
// for an empty name or one with a '/', FileError naming the path if a file cannot be written.
MapServerFiles writeMapServerMap(const std::string& dir, const std::string& name, const OccupancyGrid& grid);

}  // namespace rgnav
