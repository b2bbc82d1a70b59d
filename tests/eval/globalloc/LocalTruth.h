// LocalTruth: where a true (world) pose lies in a SLAM-built map. A SLAM map is not the world
// moved rigidly: in a 30 m floor its scans' corrected poses lie up to some decimetres off any
// single placement (MappingRun's pose errors), so one world-to-map transform would blame the
// localizer for the map's own distortion. The truth for localizing in the map is where the map
// holds the place: the world-to-map transform fitted (weighted least squares, Umeyama/Kabsch in
// 2D) to the mapped scans near the pose, each scan pairing its true position with its corrected
// one (Gaussian weights of sigmaM around the pose, scans within 2 sigmaM). Where the scans near
// the pose do not spread (a robot that stood still), the rotation is the global one.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/common/Pose2D.h"

namespace rgnav {

struct ScanPlacement {
  Eigen::Vector2d world = Eigen::Vector2d::Zero();  // true position
  Eigen::Vector2d map = Eigen::Vector2d::Zero();    // corrected position in the map
};

// Whether estimate `a` lies within `m` metres and `rad` radians of the truth `b` (the success
// test of the global localization and kidnap evaluations).
bool poseWithin(const Pose2D& a, const Pose2D& b, double m, double rad);

class LocalTruth {
 public:
  // `mapToWorld`: the global placement, used where no mapped scan is near.
  LocalTruth(std::vector<ScanPlacement> scans, const Pose2D& mapToWorld, double sigmaM = 1.5);

  Pose2D toMap(const Pose2D& world) const;

 private:
  std::vector<ScanPlacement> scans_;
  Pose2D worldToMap_;
  double sigmaM_;
};

}  // namespace rgnav
