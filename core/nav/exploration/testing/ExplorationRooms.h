// ExplorationRooms: RG maps for the exploration tests, built from rooms drawn in the map frame: a
// region's line map from wall segments and its 15 cm freespace from free rectangles (what the
// kernel gives a region: the floor the robot saw, here exactly the rectangles), each in its own
// region frame; doors with their crossing points 0.5 m off the door's line (the detector's
// crossing offset), a side's region none while the robot has not passed the door.
#pragma once

#include <vector>

#include "core/nav/planning/PlanningMap.h"

namespace rgnav::testing {

struct FreeRect {
  Eigen::Vector2d min = Eigen::Vector2d::Zero(), max = Eigen::Vector2d::Zero();  // map frame
};

// `walls` and `free` in the map frame; stored in `frame`.
RegionView exploredRegion(RegionId id, const Pose2D& frame, const std::vector<Segment2>& walls,
                          const std::vector<FreeRect>& free);

// A door between gateway points `a` and `b` (map frame). Side A lies to the left of a→b, side B to
// the right; crossing point 0 is side A's, 1 side B's; a side whose region is none has no crossing
// index yet (as the kernel gives a door it saw from one side).
GatewayView door(GatewayId id, const Eigen::Vector2d& a, const Eigen::Vector2d& b, RegionId sideA, RegionId sideB);

// The map of these regions and gateways, revision 1.
PlanningMap planningMap(std::vector<RegionView> regions, std::vector<GatewayView> gateways);

}  // namespace rgnav::testing
