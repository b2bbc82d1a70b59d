// segmentCrossing: where two line segments in the plane cross. The passage tracker uses it to
// find the robot's path crossing a gateway (a traversal), the door evaluation to find the path
// crossing a ground-truth door line.
#pragma once

#include <Eigen/Core>
#include <optional>

namespace rgnav {

// The point where segment p0-p1 crosses segment a-b (touching an end counts); nullopt if they
// do not cross or are parallel.
inline std::optional<Eigen::Vector2d> segmentCrossing(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                                                      const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
  const Eigen::Vector2d d = p1 - p0, e = b - a;
  const double den = cross(d, e);
  if (den == 0.0) return std::nullopt;
  const double t = cross(a - p0, e) / den, u = cross(a - p0, d) / den;
  if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0) return std::nullopt;
  return p0 + t * d;
}

}  // namespace rgnav
