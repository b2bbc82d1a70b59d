// Convex polygons for comparing object hypotheses: convex hull (Andrew's monotone chain), area,
// intersection by Sutherland-Hodgman clipping, point inside.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace rgnav {

// Vertices in counter-clockwise order.
using Polygon = std::vector<Eigen::Vector2d>;

// The convex hull of `points`, counter-clockwise, without collinear vertices.
Polygon convexHull(std::vector<Eigen::Vector2d> points);

// Area of a simple polygon given counter-clockwise (negative if clockwise).
double polygonArea(const Polygon& polygon);

// Area of the intersection of two convex counter-clockwise polygons.
double intersectionArea(const Polygon& a, const Polygon& b);

// True if `p` lies inside the convex counter-clockwise `polygon` grown by `marginM`; false for
// fewer than 3 vertices.
bool insideConvex(const Polygon& polygon, const Eigen::Vector2d& p, double marginM);

}  // namespace rgnav
