// GatewaySegment: a gateway line of a region, given in the region's own frame (thesis 2.1.2).
// Region descriptions use it to keep what lies behind a gateway out of the region (thesis 5.2:
// "only measurements inside the region are considered") and to count the gateway as a closed
// part of the region border (completeness).
#pragma once

#include <Eigen/Core>

namespace rgnav {

struct GatewaySegment {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
};

}  // namespace rgnav
