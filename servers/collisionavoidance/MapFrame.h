// MapFrame: where the odometry frame lies in the map frame, for the Collision Avoidance module,
// which drives in the odometry frame (its obstacle grid, its chains, the Low-Level Drive) toward
// targets given in the map frame. Pose source "odometry": the map frame is the odometry frame.
// The other pose sources give mapFromOdometry = mapPose(scan) ⊕ ⊖odometry(scan) of one scan known
// in both frames (MapFrameSource.h): "groundtruth" (the simulator's GroundTruth, for evaluations
// that take localization out of the picture), "scanmapper" (the ScanMapper's corrected poses: the
// map being built, while mapping) and "localization" (the Localization module's estimate: a known
// map).
#pragma once

#include <string>

#include "core/common/Pose2D.h"

namespace rgnav {

enum class PoseSource { Odometry, GroundTruth, ScanMapper, Localization };
// ConfigError for anything but "odometry", "groundtruth", "scanmapper" and "localization".
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
