// writeDebugImage: a PNG of one evaluated map for a person to look at, 3 x 3 pixels per grid
// cell, north up. Cell fill: white free, dark gray building, ground-truth blobs green (matched),
// red (missed), light blue (speck, not counted), violet (seen from no reachable place, not
// counted). The centre pixel of each cell a detection claims: dark green (match), magenta
// (false detection), blue (ignored). The top-left pixel of each cell a laser return fell into:
// black.
#pragma once

#include <string>
#include <vector>

#include "core/raster/OccupancyGrid.h"
#include "tests/eval/objects/FurnitureTruth.h"
#include "tests/eval/objects/Matching.h"

namespace rgnav {

void writeDebugImage(const std::string& path, const OccupancyGrid& world, const FurnitureTruth& truth,
                     const std::vector<Detection>& detections, const MatchResult& match,
                     const std::vector<bool>& hitCells);

}  // namespace rgnav
