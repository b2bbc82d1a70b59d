// TourPlanner: a route that visits every ground-truth room a round robot can reach. A room is
// reachable if one of its cells is traversable (GridPlanner inflation) and connected to the start
// through traversable cells; its visiting point is such a cell farthest from any obstacle (so the
// laser sees the room). Rooms are visited greedily, always the one cheapest to reach next by
// path cost (nearest-neighbour tour, Rosenkrantz, Stearns, Lewis, SIAM J. Comput. 6, 1977); each
// leg is a GridPlanner path, so the route passes through the doors between rooms.
#pragma once

#include <vector>

#include "core/common/Pose2D.h"
#include "core/sim/GroundTruth.h"
#include "core/sim/motion/GridPlanner.h"

namespace rgnav {

struct RoomVisit {
  int room = -1;
  WorldPoint goal;             // the visiting point
  std::size_t routeIndex = 0;  // the route waypoint that is the visiting point
};

struct Tour {
  std::vector<WorldPoint> route;       // starts at the start position, ends at the last visit
  std::vector<RoomVisit> visits;       // in visiting order
  std::vector<int> unreachableRooms;   // ascending room IDs
};

// Throws InvalidArgumentError if the ground truth does not share the grid's geometry,
// StartBlockedError if the robot does not fit at `start`, ConfigError for a bad configuration.
Tour planTour(const OccupancyGrid& grid, const GroundTruth& truth, const Pose2D& start,
              const GridPlannerConfig& config = {});

}  // namespace rgnav
