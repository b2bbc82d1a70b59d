// writeDoorImage: a PNG of one evaluated map for a person to look at, kScale x kScale pixels
// per grid cell, north up. Cells: white free, dark gray blocked. Ground-truth lines: green
// (counted, matched), red (counted, missed), orange (not counted). Confirmed gateways, drawn
// between their gateway points: blue (match), magenta (false), cyan (ignored).
#pragma once

#include <string>
#include <vector>

#include "core/gateways/passages/PassageTracker.h"
#include "core/raster/OccupancyGrid.h"
#include "tests/eval/doors/DoorMatching.h"
#include "tests/eval/doors/DoorTruth.h"

namespace rgnav {

void writeDoorImage(const std::string& path, const OccupancyGrid& world, const std::vector<TruthDoor>& doors,
                    const std::vector<TrackedGateway>& gateways, const DoorMatch& match);

}  // namespace rgnav
