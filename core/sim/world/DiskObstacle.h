// DiskObstacle: a round obstacle that is not part of the world's grid (a walking person): the
// robot can run into it and the laser sees it.
#pragma once

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct DiskObstacle {
  WorldPoint centre;
  double radius = 0.25;  // m
};

}  // namespace rgnav
