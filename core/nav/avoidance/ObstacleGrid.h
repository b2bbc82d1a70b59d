// ObstacleGrid: the one interface through which sensors tell the Collision Avoidance where
// obstacles are: a 2D grid in the odometry frame (Occupied = obstacle, Free = seen free,
// Unknown = not seen) with the time it shows, and, from sensors that can tell, which of the
// obstacles move (people: the robot keeps a speed from which it stops before they could reach
// it). The laser's LaserObstacleMap makes one; the stereo obstacle grid of the vision modules is
// another.
#pragma once

#include <string>

#include "core/common/SensorData.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct ObstacleGrid {
  std::string source;  // "laser", "stereo", ...
  Timestamp stamp = 0.0;
  OccupancyGrid cells;
  OccupancyGrid moving;  // Occupied: a moving obstacle (on the geometry of `cells`); empty: not told
};

}  // namespace rgnav
