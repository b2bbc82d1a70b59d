// exportMapFiles: what RGMappingKernel::exportMap writes: <dir>/<name>.rgmap.json, .svg and
// .png, and on request the global metric map <dir>/<name>.pgm + .yaml (ROS map_server).
#pragma once

#include <string>

#include "core/rgmap/kernel/RgMappingKernel.h"

namespace rgnav {

// Creates `dir` if needed; returns the paths written, one per line. Throws InvalidArgumentError
// for an empty directory or a name with a '/', FileError when a file cannot be written,
// NotAvailableError for a map without scans.
std::string exportMapFiles(const RgMappingKernel& kernel, const std::string& dir, const std::string& name,
                           bool occupancy);

}  // namespace rgnav
