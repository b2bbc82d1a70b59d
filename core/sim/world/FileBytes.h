// readFileBytes: a whole (YAML) file into memory, every failure a FileError naming the
// path. The world loaders read their YAML files with it; images come through core/raster/ImageFile.h.
#pragma once

#include <string>

namespace rgnav {

std::string readFileBytes(const std::string& path);

}  // namespace rgnav
