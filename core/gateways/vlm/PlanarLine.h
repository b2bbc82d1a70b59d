// PlanarLine: an infinite 2D line (a point on it and a unit direction) and the few operations
// the virtual line model of thesis 4.1.1 needs: intersections (gateway points are the
// intersections of the virtual lines), signed offsets (which side of a line the robot is on) and
// where a laser ray meets a line (the freespace measures of 4.1.2.2).
#pragma once

#include <Eigen/Core>
#include <optional>

namespace rgnav {

struct PlanarLine {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // unit

  // The unit normal to the left of `direction`.
  Eigen::Vector2d leftNormal() const { return {-direction.y(), direction.x()}; }
  // Distance of p from the line, positive to the left of `direction`.
  double signedOffset(const Eigen::Vector2d& p) const { return leftNormal().dot(p - point); }
  // The same line moved by `offset` along leftNormal().
  PlanarLine shifted(double offset) const { return {point + offset * leftNormal(), direction}; }
  // The parallel line through p.
  PlanarLine parallelThrough(const Eigen::Vector2d& p) const { return {p, direction}; }
};

// The line from `from` through `to`, directed that way; none if the points coincide (1 µm).
std::optional<PlanarLine> lineThrough(const Eigen::Vector2d& from, const Eigen::Vector2d& to);

// The intersection of a and b; none if they are parallel within `minSine` (sine of the angle).
std::optional<Eigen::Vector2d> intersect(const PlanarLine& a, const PlanarLine& b, double minSine = 1e-6);

// The distance t > 0 along the unit ray origin + t * ray at which it meets `line`; none if the
// ray runs parallel to the line or away from it.
std::optional<double> rayDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& ray, const PlanarLine& line);

// Smallest angle between the undirected lines a and b, in [0, pi/2].
double angleBetween(const PlanarLine& a, const PlanarLine& b);

}  // namespace rgnav
