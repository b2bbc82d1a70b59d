// GatewayPoints: the four gateway points of a virtual line model (thesis 4.1.1.2: "the gateway
// points are defined by the intersections of those virtual lines"), in the order of the convex
// quadrangle they span: hidden-left, front-left, front-right, hidden-right. The side
// hidden-left/hidden-right is where the robot enters the gateway area.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>

#include "core/common/Pose2D.h"

namespace rgnav {

enum GatewayPointIndex : std::size_t { kHiddenLeft = 0, kFrontLeft = 1, kFrontRight = 2, kHiddenRight = 3 };

using GatewayPoints = std::array<Eigen::Vector2d, 4>;

// The gateway points of the ideal VLM of a gateway centred at the origin and entered along +x:
// the corners of the square gateway area of side `width` (thesis 4.1.1: hallways of about the
// same width meet), hidden-left (-w/2, w/2) first.
GatewayPoints squareGatewayArea(double width);

// The mean of the four points, the gateway centre the observation distances refer to.
Eigen::Vector2d gatewayCentre(const GatewayPoints& points);

// The points given in the frame of `pose`, expressed in the frame `pose` is given in.
GatewayPoints transformed(const GatewayPoints& points, const Pose2D& pose);

// Largest distance between corresponding points.
double largestPointDistance(const GatewayPoints& a, const GatewayPoints& b);

// How far `p` lies past the entrance (the hidden line through hidden-left and hidden-right)
// towards the front line; negative before the entrance.
double depthPastEntrance(const GatewayPoints& points, const Eigen::Vector2d& p);

}  // namespace rgnav
