// Person: what the ground truth knows of one person walking through the simulated world (Crowd.h):
// a cylinder seen from above, where it is and how fast it walks.
#pragma once

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct Person {
  WorldPoint position;
  WorldPoint velocity;  // m/s, over the last step
  double radius = 0.25;  // m
};

}  // namespace rgnav
