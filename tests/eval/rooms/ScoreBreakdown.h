// breakDownScore: where the room scores (RoomScoring.h) of one map lose, for finding out which
// part of the mapping to improve.
// Recall, as means over the ground-truth rooms of pixel shares:
//   - ceiling: room pixels free in the world (the furnished floor plan), none for a room the tour
//     cannot reach: what freespace alone can cover, since a robot maps no room it cannot get
//     into and sees no floor under furniture (regions add only the furniture they enclose,
//     RegionHoles.h, so covered may exceed it);
//   - covered: room pixels some segment claims;
//   - the recall itself: room pixels the room's best segment claims (covered - recall: the room
//     is split between segments).
// Precision, as shares of all scored segment pixels (pooled), for the pixels outside each
// segment's best room:
//   - off-room: on no room (GT separator lines and specks);
//   - leaked: in a room that another segment has as its best room and also claims (the segment
//     sees into a neighbour that has a region of its own: through a gateway that does not cut its
//     beams, or from scans taken beyond one);
//   - merged: in a room no other claiming segment has as its best room (rooms that share one
//     region, or a room whose region claims less of it).
#pragma once

#include <span>

#include "core/raster/OccupancyGrid.h"
#include "core/sim/GroundTruth.h"
#include "tests/eval/objects/FurnitureTruth.h"
#include "tests/eval/rooms/RoomScoring.h"

namespace rgnav {

struct ScoreBreakdown {
  double ceilingMean = 0.0;
  double coveredMean = 0.0;
  double offRoomShare = 0.0;
  double leakedShare = 0.0;
  double mergedShare = 0.0;
};

// `segments` and `score` as scoreRooms took and gave them; `world` has the ground truth's geometry.
ScoreBreakdown breakDownScore(const GroundTruth& truth, const OccupancyGrid& world,
                              std::span<const SegmentPixels> segments, const RoomScore& score,
                              std::span<const int> unreachableRooms);

// The mean share of each ground-truth room's pixels that furniture covers (FurnitureTruth.h: free
// in X.png, not in X_furnitures.png). The rooms of the ground truth include it; no laser sees
// under it, and of furniture against a wall not even its back. Throws InvalidArgumentError if
// `furniture` differs in size from the ground truth.
double furnitureShareMean(const GroundTruth& truth, const FurnitureTruth& furniture);

}  // namespace rgnav
