// doorTruth: which ground-truth door lines of an IPA floor plan (GroundTruth::doors, the
// separators drawn in X_gt_segmentation.png) count as doors a narrow-passage detector should
// find. floorplans/SOURCES.md warns that not every separator is a doorway (lab_b_scan has lines
// along walls, lab_intel an L-shaped one). Our rule, in this order:
//   1. kNotBetweenRooms: the line does not have two different GT rooms on its two sides;
//   2. kUnreachable: a room on either side is one the tour cannot reach (the robot never gets
//      through it, so the passage cannot be traversed and is not counted);
//   3. kNotNarrow: the line is not door-like (wider than maxDoorWidthM) or not narrower than the
//      free space on both sides of it (narrowerFactor times the free width parallel to the line,
//      sideOffsetM away from it, on the empty map X.png): a region border drawn across a hallway
//      or an open room is no narrow passage;
//   4. kNotApproached: the robot's path never came within approachM of the line's midpoint, the
//      detector's D_NP^max: no observation of it may count (thesis 6.1.3 does not consider "a door
//      the robot passed by but did not approach" either).
// Everything else is counted. Whether the path crossed the line is noted for the traversal
// score (thesis table 6.1 counts the gateways of the RG map, made when a passage is traversed).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/raster/OccupancyGrid.h"
#include "core/sim/GroundTruth.h"

namespace rgnav {

struct DoorRule {
  double maxDoorWidthM = 2.0;       // door-like: at most this wide
  double sideOffsetM = 0.6;         // where the space beside the line is measured
  double narrowerFactor = 0.9;      // narrower than the space on both sides: width < factor * that
  double approachM = 3.0;           // the detector's D_NP^max
};

enum class DoorExclusion { kNone, kNotBetweenRooms, kUnreachable, kNotNarrow, kNotApproached };

struct TruthDoor {
  DoorLine line;
  Eigen::Vector2d midpoint = Eigen::Vector2d::Zero();
  double widthM = 0.0;
  double sideWidthM[2] = {0.0, 0.0};  // free space parallel to the line on either side
  DoorExclusion exclusion = DoorExclusion::kNone;
  bool traversed = false;  // the path crossed the line
};

// `emptyMap` is X.png (no furniture) in the ground truth's geometry; `path` the robot's true
// positions along the tour.
std::vector<TruthDoor> doorTruth(const GroundTruth& truth, const OccupancyGrid& emptyMap,
                                 const std::vector<int>& unreachableRooms, const std::vector<Eigen::Vector2d>& path,
                                 const DoorRule& rule);

std::string exclusionName(DoorExclusion exclusion);

}  // namespace rgnav
