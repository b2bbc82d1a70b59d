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
#pragma once

#include <string>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// Unknown or missing keys and bad values are ConfigErrors naming the file and key; a missing
// image a FileError naming the YAML file and the image path; a bad image a FormatError.
OccupancyGrid loadMapServerYaml(const std::string& yamlPath);

}  // namespace rgnav
