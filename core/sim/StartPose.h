// openestPose: a default start for the simulated robot: the free cell farthest from any wall,
// heading 0. From there the rooms of a building are usually all reachable.
#pragma once

#include "core/common/Pose2D.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// InvalidArgumentError if the grid has no free cell.
Pose2D openestPose(const OccupancyGrid& grid);

}  // namespace rgnav
