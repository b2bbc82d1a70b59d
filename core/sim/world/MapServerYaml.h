// loadMapServerYaml: ROS map_server map files (YAML + PGM or PNG image), read as map_server's
// "trinary" mode does: p = (255 - gray) / 255 (p = gray / 255 with negate), p > occupied_thresh
// occupied, p < free_thresh free, otherwise unknown. Colour images are converted to gray by
// luminance (core/raster/ImageFile.h), not map_server's channel average.
//
//   image: map.pgm            # required, relative to the YAML file's folder
//   resolution: 0.05          # required, m per pixel
//   origin: [x, y, yaw]       # required, pose of the image's bottom-left pixel; yaw must be 0
//   occupied_thresh: 0.65     # required, in [0, 1]
//   free_thresh: 0.196        # required, in [0, 1], below occupied_thresh
//   negate: 0                 # optional, 0/1 or true/false
//   mode: trinary             # optional; trinary is the only mode supported
// plus the optional keys of a navigation task (start, goal, ...: NavigationTask.h).
#pragma once

#include <optional>
#include <string>

#include "core/raster/OccupancyGrid.h"
#include "core/sim/world/NavigationTask.h"

namespace rgnav {

struct MapServerWorld {
  OccupancyGrid grid;
  std::optional<NavigationTask> task;
};

// Unknown or missing keys and bad values are ConfigErrors naming the file and key; a missing
// image a FileError naming the YAML file and the image path; a bad image a FormatError.
MapServerWorld loadMapServerWorld(const std::string& yamlPath);
// The map alone (the task keys are checked all the same).
OccupancyGrid loadMapServerYaml(const std::string& yamlPath);

}  // namespace rgnav
