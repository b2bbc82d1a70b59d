// readFileBytes: a whole (image or YAML) file into memory, every failure a FileError naming the
// path. The one place the world loaders touch the file system for reading.
#pragma once

#include <string>

namespace rgnav {

std::string readFileBytes(const std::string& path);

}  // namespace rgnav
