// Distance / angle test of the keyframe filter (thesis 5.2).
#include "core/slam/KeyframeFilter.h"

#include <cmath>

namespace rgnav {

bool isKeyframe(const Pose2D& lastKeyframeOdometry, const Pose2D& odometry, const KeyframeFilterConfig& config) {
  const Pose2D motion = between(lastKeyframeOdometry, odometry);
  return std::hypot(motion.x, motion.y) >= config.minTranslation || std::abs(motion.theta) >= config.minRotation;
}

}  // namespace rgnav
