// PathShortcut: turns an 8-connected cell path into few waypoints by greedy line-of-sight
// shortcutting ("string pulling", cf. the post-smoothing of Daniel, Nash, Koenig, Felner,
// "Theta*: Any-Angle Path Planning on Grids", JAIR 39, 2010): from each kept cell the path jumps
// to the farthest later cell whose straight connection keeps, at every half-cell sample, the
// clearance min(desired, clearance of the replaced cell path at the same fraction of the way).
// A shortcut therefore never brings the path closer to a wall than the cell path came there,
// nor closer than `desired` where the cell path had more room.
#pragma once

#include <span>
#include <vector>

#include "core/nav/grid/ClearanceMap.h"

namespace rgnav {

// The kept cells, first and last included; `path` must lie inside the grid.
std::vector<CellIndex> shortcutPath(const ClearanceMap& map, std::span<const CellIndex> path,
                                    double desiredClearance);

}  // namespace rgnav
