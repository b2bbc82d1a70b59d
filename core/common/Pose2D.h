// Pose2D: a planar pose (x, y in metres, theta in radians) and its composition operators.
#pragma once

#include <cmath>

namespace rgnav {

struct Pose2D {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;

  friend bool operator==(const Pose2D&, const Pose2D&) = default;
};

// Wraps an angle into (-pi, pi].
inline double normalizeAngle(double a) {
  a = std::remainder(a, 2.0 * M_PI);
  return a <= -M_PI ? a + 2.0 * M_PI : a;
}

// a ⊕ b: b expressed in a's frame, returned in the frame a is expressed in.
inline Pose2D compose(const Pose2D& a, const Pose2D& b) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  return {a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y, normalizeAngle(a.theta + b.theta)};
}

// ⊖a: the inverse transform of a.
inline Pose2D inverse(const Pose2D& a) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  return {-c * a.x - s * a.y, s * a.x - c * a.y, normalizeAngle(-a.theta)};
}

// The pose of b relative to a: ⊖a ⊕ b.
inline Pose2D between(const Pose2D& a, const Pose2D& b) { return compose(inverse(a), b); }

}  // namespace rgnav
