// KeyframeFilter: thesis 5.2 ("scans are expected to be acquired at certain distance or angle
// intervals; the SMM buffers the incoming laser scans and filters them"): a scan becomes a
// keyframe when the odometry moved at least a distance or turned at least an angle since the
// last keyframe. The first scan always is one. Stateless: the last keyframe's odometry comes from
// the caller (SlamState), so nothing extra has to survive a restart.
#pragma once

#include "core/common/Pose2D.h"
#include "core/slam/SlamConfig.h"

namespace rgnav {

// True if a scan taken at `odometry` is a keyframe, given the odometry of the last keyframe.
bool isKeyframe(const Pose2D& lastKeyframeOdometry, const Pose2D& odometry, const KeyframeFilterConfig& config);

}  // namespace rgnav
