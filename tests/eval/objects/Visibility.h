// Visibility of ground-truth furniture from where the robot can be: a blob counts for recall
// only if a straight line of sight within laser range joins one of its cells to a cell the
// robot's centre (= the laser) can reach, i.e. a traversable cell connected to the start
// (GridPlanner, 0.25 m robot radius). Lines of sight are sampled from the centre of every blob
// cell with a free 4-neighbour in 1 degree steps; a line ends at the first blocked cell that is
// not part of the blob. Walls and other furniture block; the blob itself does not.
#pragma once

#include <vector>

#include "core/raster/OccupancyGrid.h"
#include "tests/eval/objects/FurnitureTruth.h"

namespace rgnav {

// Marks every blob with no exclusion yet that no reachable cell sees as kNotVisible.
// `reachable` is row-major over `grid`.
void markInvisible(FurnitureTruth& truth, const OccupancyGrid& grid, const std::vector<bool>& reachable,
                   double maxRangeM);

}  // namespace rgnav
