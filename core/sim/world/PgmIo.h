// PGM reading and writing (Netpbm "pgm" format: binary P5 and plain/ASCII P2), the image format
// of ROS map_server maps. Reading accepts maxval 1..65535 and scales to 8 bit; writing produces
// maxval 255.
#pragma once

#include <string>

#include "core/sim/world/Image.h"

namespace rgnav {

enum class PgmEncoding { Binary, Ascii };  // P5, P2

// True if `bytes` start with a P5 or P2 magic number.
bool isPgm(const std::string& bytes);

// Decodes a PGM held in memory; `path` names it in errors. A malformed header or too few pixel
// values is a FormatError naming the path and the line.
GrayImage decodePgm(const std::string& bytes, const std::string& path);

// Writes the image atomically; throws FileError naming the path.
void writePgm(const std::string& path, const GrayImage& image, PgmEncoding encoding);

}  // namespace rgnav
