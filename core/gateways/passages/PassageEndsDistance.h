// passageEndsDistance: how far apart two narrow passages' gateway points are, for deciding that
// they are one door. The passage tracker associates a hypothesis with a track by it, the RG
// Mapping Kernel a door reported under a new detector ID with a known door.
#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace rgnav {

struct PassageEndsDistance {
  double distanceM = 0.0;  // the larger of the two point distances in the better pairing
  bool swapped = false;    // that pairing matches a0 with b1 (a door seen from its other side)
};

inline PassageEndsDistance passageEndsDistance(const Eigen::Vector2d& a0, const Eigen::Vector2d& a1,
                                               const Eigen::Vector2d& b0, const Eigen::Vector2d& b1) {
  const double straight = std::max((a0 - b0).norm(), (a1 - b1).norm());
  const double swapped = std::max((a0 - b1).norm(), (a1 - b0).norm());
  return {std::min(straight, swapped), swapped < straight};
}

}  // namespace rgnav
