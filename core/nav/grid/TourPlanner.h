// TourPlanner: a route that visits every room a round robot can reach, given the room of each
// grid cell (the simulator takes them from its ground truth, core/sim/GroundTruthTour.h). A room
// is reachable if one of its cells is traversable (GridPlanner inflation) and connected to the
// start through traversable cells; its visiting point is such a cell farthest from any obstacle
// (so the laser sees the room). Rooms are visited greedily, always the one cheapest to reach next by
// path cost (nearest-neighbour tour, Rosenkrantz, Stearns, Lewis, SIAM J. Comput. 6, 1977); each
// leg is a GridPlanner path, so the route passes through the doors between rooms.
#pragma once

#include <span>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/nav/grid/GridPlanner.h"

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

// `cellRooms`: per grid cell in row-major order a room ID 0..roomCount-1, or -1 for cells in no
// room. Throws InvalidArgumentError if `cellRooms` does not have one entry per cell or
// `roomCount` is negative, StartBlockedError if the robot does not fit at `start`, ConfigError
// for a bad configuration.
Tour planTour(const OccupancyGrid& grid, std::span<const int> cellRooms, int roomCount, const Pose2D& start,
              const GridPlannerConfig& config = {});

}  // namespace rgnav
