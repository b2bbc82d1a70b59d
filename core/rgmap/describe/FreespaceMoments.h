// freespaceMoments: size, first and second order moments and main axes of a region's freespace
// (thesis 2.1.1, table 2.1 "2D freespace and its 1st/2nd order moments"; "from the 2D freespace
// feature further information like size or center of gravity ... is calculated"). Each cell of
// the RegionFreespace is a uniformly filled square of side s with a weight:
//   - free cells weigh 1;
//   - occupied cells with a free 4-neighbour weigh 1/2: a wall runs somewhere through its cells,
//     on average through their middle, so about half of such a cell belongs to the freespace;
//   - other cells weigh 0.
//   areaM2     = sum of weights * s^2,
//   centroid   = weighted mean of the cell centres (first moments / area),
//   covariance = weighted second central moments / area, each cell adding its own s^2 / 12 on the
//                diagonal (a fully free L x W rectangle gives exactly diag(L^2, W^2) / 12),
//   main axes  = eigenvalues and eigenvectors of the covariance; majorAxisAngleRad in [0, pi) is
//                the direction of the larger one (for a rectangle: along its longer side).
// Deliberate difference: the thesis' 1-bit map only knows free cells; counting them alone would
// make every room smaller by half a cell (7.5 cm) along its whole outline (6 % for a 7 x 4.4 m
// room), so the exported map's free area (FreespaceBitmap::freeCount() * s^2) is that much
// smaller than areaM2.
#pragma once

#include <Eigen/Core>

#include "core/rgmap/describe/RegionFreespace.h"

namespace rgnav {

struct FreespaceMoments {
  double areaM2 = 0.0;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  double majorVariance = 0.0;  // larger eigenvalue, m^2
  double minorVariance = 0.0;  // smaller eigenvalue, m^2
  double majorAxisAngleRad = 0.0;
};

// All zero for a region without free cells.
FreespaceMoments freespaceMoments(const RegionFreespace& freespace);

}  // namespace rgnav
