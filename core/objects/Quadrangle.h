// Quadrangle: a hypothesis of 2D line grouping (thesis 3.1): four line segments in cyclic order
// and the corners where the lines of consecutive sides intersect.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

#include "core/lines/LineSegment.h"
#include "core/objects/ConvexPolygon.h"

namespace rgnav {

using SideCycle = std::array<std::size_t, 4>;

struct Quadrangle {
  SideCycle sides{};                       // indices into the grouped lines, canonical cycle
  std::array<Eigen::Vector2d, 4> corners;  // corners[m]: lines of sides[m] and sides[(m+1)%4] meet
};

// The same cycle started at its smallest index and run towards the smaller of that index's two
// neighbours, so that every quadrangle has one spelling.
SideCycle canonicalCycle(const SideCycle& cycle);

// The quadrangle of the lines lines[cycle[0..3]] in that cyclic order (made canonical). Throws
// InvalidArgumentError if two consecutive sides are parallel.
Quadrangle makeQuadrangle(const std::vector<LineSegment>& lines, const SideCycle& cycle);

// The convex hull of the corners, counter-clockwise.
Polygon outline(const Quadrangle& quadrangle);

}  // namespace rgnav
