// printListing: the --list output of the room evaluation, one comment line per item, for finding
// out why a map scores as it does:
//   - every ground-truth room: centre, pixels, recall and its best region;
//   - every scored region: its scans (ID range, true positions' bounding box, how many lie in
//     each GT room, -1 = on no room), how many of them lie beyond one of its own doors (the true
//     position is nearer the crossing point of the door's other side, within kBeyondRadiusM of the
//     door's midpoint: the robot had crossed the final door line but the scan stayed in the region,
//     so its beams into the next room are not cut), then its pixels, precision, best room and every
//     room holding >= 5 % of its pixels;
//   - every gateway in the world frame with its regions, traversals and whether it is neutralised.
#pragma once

#include "core/sim/GroundTruth.h"
#include "tests/eval/rooms/MappingRun.h"
#include "tests/eval/rooms/RoomScoring.h"

namespace rgnav {

inline constexpr double kBeyondRadiusM = 1.5;

void printListing(const RoomScore& score, const GroundTruth& truth, const MappingRun& run);

}  // namespace rgnav
