// readGrayImage: loads a PNG or PGM (P5/P2) file as 8-bit gray, recognising the format by its
// magic number, not its file name. Used by every map loader.
#pragma once

#include <string>

#include "core/sim/world/Image.h"

namespace rgnav {

// A missing or unreadable file is a FileError, anything other than a valid PNG or PGM a
// FormatError; both name the path.
GrayImage readGrayImage(const std::string& path);

}  // namespace rgnav
