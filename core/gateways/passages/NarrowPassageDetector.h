// NarrowPassageDetector: laser-based detection of narrow passages in one scan (thesis 4.2.1).
// For a viewing direction α_m the field of view is split into a right range
// α_m - Δα < α < α_m and a left range α_m < α < α_m + Δα; the closest point of each is P_right
// and P_left. The walk from each towards the other (GatewayPointWalk.h) declares the passage
// valid or invalid and yields additional gateway-point candidates; every pair of candidates is
// then checked: D_lr^min < D_lr < D_lr^max, the line of sight α_m crosses the pair's segment at
// P_is with D_NP = |P_is - P_sc| < D_NP^max, α_NP >= α_NP^min, and the scan sees open space
// behind the gateway line (OpenSpaceBehind.h). Of the valid pairs, the one with the minimum
// width is the hypothesis for that viewing direction.
//
// Where we differ from the thesis (its rules alone report every gap between table legs and
// every hallway narrower than D_lr^max in the furnished IPA floor plans):
//   - viewing directions: the thesis uses the robot's heading only; we use every viewingStepRad
//     across the field of view (the heading included), so that doors to the side of a hallway
//     are found as the robot passes them;
//   - one more candidate per side: the point of each walk nearest to the other walk's end (where
//     a door meets a side wall, the walk turns the corner and ends deep in the room);
//   - gateway points (JambSurfaces.h): both bound a surface of minJambLengthM and are not the far
//     side of a depth jump; at least one ends its surface towards the passage and continues the
//     gateway line outwards (a wall end in line with the passage: a door jamb, or a partition's
//     end facing a wall). This rejects table legs and lines across hallways;
//   - open space behind the line is counted on beams that do not hit the gateway points' own
//     surfaces;
//   - across directions the minimum-width rule goes on: the narrowest pair wins, and a wider pair
//     whose points overlap it in the scan (the same opening seen askew, or an opening seen
//     through it) is dropped; identical pairs are reported once, with the smallest D_NP.
#pragma once

#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"
#include "core/gateways/passages/PassageConfig.h"
#include "core/gateways/passages/PassageHypothesis.h"

namespace rgnav {

class NarrowPassageDetector {
 public:
  // Throws ConfigError for a bad configuration.
  explicit NarrowPassageDetector(const NarrowPassageConfig& config = {});

  // The narrow passages in `scan`, taken by a sensor at `sensorPose` (world frame); gateway
  // points in the world frame, nearest passage first.
  std::vector<PassageHypothesis> detect(const LaserScan& scan, const Pose2D& sensorPose) const;

 private:
  NarrowPassageConfig config_;
};

}  // namespace rgnav
