// MapFrame: where the odometry frame lies in the map frame, for the Collision Avoidance module,
// which drives in the odometry frame (its obstacle grid, its chains, the Low-Level Drive) toward
// targets given in the map frame. Pose source "odometry": the map frame is the odometry frame.
// Pose source "groundtruth" (the simulator's GroundTruth, for evaluations that take localization
// out of the picture): mapFromOdometry = truePose(scan) ⊕ ⊖odometry(scan) of the latest scan.
// A localization module would give the same offset from its estimate.
#pragma once

#include <string>

#include "core/common/Pose2D.h"

namespace rgnav {

enum class PoseSource { Odometry, GroundTruth };
// ConfigError for anything but "odometry" and "groundtruth".
PoseSource parsePoseSource(const std::string& text);

// The map pose of the odometry frame's origin, from one pose known in both frames.
inline Pose2D mapFromOdometry(const Pose2D& inMap, const Pose2D& inOdometry) {
  return compose(inMap, inverse(inOdometry));
}

inline Pose2D toOdometry(const Pose2D& mapFromOdometry, const Pose2D& inMap) {
  return compose(inverse(mapFromOdometry), inMap);
}

inline Pose2D toMap(const Pose2D& mapFromOdometry, const Pose2D& inOdometry) {
  return compose(mapFromOdometry, inOdometry);
}

}  // namespace rgnav
