// exportRgMapJson: an RG Map as a documented, versioned JSON file for users of the map (thesis 2.1:
// regions with their line maps and descriptions, gateways with their classes and sides, the RG
// Graph of 2.1.3): {"format": "rgnav-rgmap", "version": 2, ...}. The schema, with every field,
// its unit and frame, is RGMAP_JSON.md beside this file.
// Not the kernel's checkpoint (RgMapCodec.h), which holds the whole state with every scan so that
// the kernel can resume; this is the map as a user sees it, without the scans, and is not read
// back by the kernel.
// Deterministic: the same snapshot always gives the same bytes (fields in a fixed order, values
// rounded to 1 mm, 0.1 mrad and 1e-4, ExportNumbers.h), written compactly on one line.
#pragma once

#include <string>

#include "core/rgmap/export/RgMapSnapshot.h"

namespace rgnav {

inline constexpr const char* kRgMapJsonFormat = "rgnav-rgmap";
inline constexpr int kRgMapJsonVersion = 2;

// The JSON text, ending in a newline.
std::string exportRgMapJson(const RgMapSnapshot& map);

// Writes exportRgMapJson(map) atomically (AtomicFile.h); throws FileError naming the path.
void writeRgMapJson(const std::string& path, const RgMapSnapshot& map);

}  // namespace rgnav
