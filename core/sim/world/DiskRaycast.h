// castToDisk: a laser beam against a round obstacle (a person's cylinder): the exact ray-circle
// intersection, for the laser to see obstacles that are not in the world grid (LaserModel).
#pragma once

#include "core/sim/world/DiskObstacle.h"

namespace rgnav {

// Metres from `from` along the world-frame direction `angle` to the disk's boundary; +inf if the
// ray misses it (a ray that only grazes it misses); 0 if `from` lies inside or on the disk.
double castToDisk(WorldPoint from, double angle, const DiskObstacle& disk);

}  // namespace rgnav
