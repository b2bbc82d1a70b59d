// SegmentVisibility: whether a straight segment between two points crosses only free space of an
// OccupancyGrid, in the collision model every planner of this library and its evaluation share.
// Points are in cell units: cell (col, row) is the closed square [col, col + 1] x [row, row + 1]
// (so its centre is (col + 0.5, row + 0.5)); outside the grid is blocked. A segment is free if
//   - it enters the interior of no blocked cell,
//   - where it runs along a grid line, the cells on both sides of the line are not both blocked,
//   - where it passes through a grid vertex, it does not squeeze between two diagonally opposite
//     blocked cells there.
// Touching a blocked cell's border or corner is allowed: the exact Euclidean shortest path bends
// around obstacle corners, touching them. This is looser than the MovingAI octile rule (a diagonal
// step needs both cardinal cells free), so every octile path is free here, and any-angle paths
// may be shorter than the octile optimum, never longer.
// The walk visits the cells the segment passes through in order (Amanatides & Woo, "A Fast Voxel
// Traversal Algorithm", 1987), with every grid-line crossing computed afresh from the start point,
// so that for points on the half-cell lattice (cell centres, grid vertices) vertex passages are
// detected exactly: equal rationals give equal correctly-rounded quotients.
#pragma once

#include <Eigen/Core>

#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// Whether the segment from `a` to `b` (cell units) is free. A point (a == b) is free if it lies in
// or on the border of a free cell.
bool segmentFree(const OccupancyGrid& grid, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

}  // namespace rgnav
