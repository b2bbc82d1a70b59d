// The default start pose (see StartPose.h).
#include "core/sim/StartPose.h"

#include "core/nav/grid/ClearanceMap.h"

namespace rgnav {

Pose2D openestPose(const OccupancyGrid& grid) {
  const ClearanceMap clearance(grid);
  CellIndex best{0, 0};
  for (int row = 0; row < grid.height(); ++row)
    for (int col = 0; col < grid.width(); ++col)
      if (clearance.at({col, row}) > clearance.at(best)) best = {col, row};
  if (grid.at(best) != Cell::Free) throw InvalidArgumentError("the world has no free cell to start in");
  const WorldPoint p = grid.center(best);
  return {p.x, p.y, 0.0};
}

}  // namespace rgnav
