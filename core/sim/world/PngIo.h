// PNG reading and writing with libpng (W3C PNG specification). Reading converts any 8/16-bit
// gray, gray+alpha, RGB, RGBA or palette PNG to 8-bit gray exactly as OpenCV's
// imread(IMREAD_GRAYSCALE) does, which the floor-plan benchmark's encoding assumes
// (floorplans/SOURCES.md): alpha dropped (not composited), 16 bit cut to the high byte,
// gray = 0.299 R + 0.587 G + 0.114 B in libpng's fixed point (OpenCV asks libpng for exactly
// this). Writing produces 8-bit gray or RGB files.
#pragma once

#include <string>

#include "core/sim/world/Image.h"

namespace rgnav {

// True if `bytes` start with the PNG signature.
bool isPng(const std::string& bytes);

// Decodes a PNG held in memory; `path` names it in errors. A damaged or truncated file is a
// FormatError naming the path.
GrayImage decodePngGray(const std::string& bytes, const std::string& path);

// Writes the image atomically; throws FileError naming the path.
void writePng(const std::string& path, const GrayImage& image);
void writePng(const std::string& path, const RgbImage& image);

}  // namespace rgnav
