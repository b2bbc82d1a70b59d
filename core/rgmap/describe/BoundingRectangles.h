// Bounding rectangles of a region's measurements (thesis 2.1.1, table 2.1 "bounding rectangle";
// 5.2: "a bounding rectangle for the scans belonging to that region, whereas only measurements
// inside the region are considered"), both computed from the measurements' convex hull
// (MeasurementHull.h):
//   - the axis-aligned box in the region frame (the thesis' bounding rectangle);
//   - the minimum-area rectangle of any orientation, which has one side on a hull edge (Freeman &
//     Shapira, "Determining the minimum-area encasing rectangle for an arbitrary closed curve",
//     1975); for a rectangular room it runs along the walls whatever the region frame.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <optional>

#include "core/objects/ConvexPolygon.h"

namespace rgnav {

struct OrientedRectangle {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double angleRad = 0.0;  // direction of the length side, in [0, pi)
  double lengthM = 0.0;   // >= widthM
  double widthM = 0.0;

  double areaM2() const { return lengthM * widthM; }
  // Counter-clockwise, starting at the corner behind and to the right of the length direction.
  std::array<Eigen::Vector2d, 4> corners() const;
};

// The axis-aligned box of the hull's vertices (empty() for an empty hull).
Eigen::AlignedBox2d axisAlignedBox(const Polygon& hull);

// The minimum-area rectangle around a convex counter-clockwise polygon (as convexHull gives it);
// nullopt for an empty one. One or two vertices give a rectangle of zero width (and length).
std::optional<OrientedRectangle> minimumAreaRectangle(const Polygon& hull);

}  // namespace rgnav
