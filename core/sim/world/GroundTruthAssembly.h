// Building blocks of the ground-truth loaders (issue 3: IPA floor plans, vector worlds; for
// evaluation programs only): a GroundTruth in a grid's geometry, and the rooms on either side
// of a door line, found by probing perpendicular to it outwards from its middle (then from its
// quarter points if the middle meets no room).
#pragma once

#include <vector>

#include "core/sim/GroundTruth.h"

namespace rgnav {

// A GroundTruth with the grid's geometry, the given per-cell labels and no doors yet.
GroundTruth groundTruthFrame(const OccupancyGrid& grid, std::vector<int> labels, int roomCount);

// Sets door.roomA (left of a->b) and door.roomB (right), -1 if no room lies within
// `maxDistance` metres on that side.
void assignDoorRooms(const GroundTruth& truth, DoorLine& door, double maxDistance);

}  // namespace rgnav
