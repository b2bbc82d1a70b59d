// ApproachTrajectory: the robot poses of approaches to a gateway for the observation sequences of
// thesis 4.1.2.3/4.1.3: the robot starts at a distance before the gateway centre and a lateral
// offset from the hallway axis and drives straight towards the gateway area, heading along the
// hallway, until it reaches its entrance (half a hallway width before the centre, the closest
// observation of the thesis). Each sampled pose carries the gateway class and its Euclidean
// distance to the gateway centre, which decreases strictly along an approach.
#pragma once

#include <vector>

#include "core/common/Pose2D.h"
#include "core/gateways/classes/GatewayClass.h"

namespace rgnav {

struct LabelledPose {
  Pose2D pose;  // in the gateway frame (gateway centre at the origin, approach along +x)
  GatewayClass gatewayClass = GatewayClass::Hallway;
  double distance = 0.0;  // m, to the gateway centre
};

struct Approach {
  double startDistance = 0.0;  // m before the gateway centre, along the hallway
  double lateralOffset = 0.0;  // m, positive to the left
  std::vector<LabelledPose> poses;
};

// Poses every `spacing` metres from x = -startDistance to x = -width/2 (always included) at
// y = lateralOffset. Throws ConfigError for a non-positive spacing or width, or a start distance
// not beyond width/2.
Approach makeApproach(GatewayClass gatewayClass, double width, double startDistance,
                      double lateralOffset, double spacing);

}  // namespace rgnav
