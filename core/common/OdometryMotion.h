// OdometryMotion: the rot1 / trans / rot2 decomposition of a relative motion between two poses
// (Thrun, Burgard, Fox, Probabilistic Robotics, 2005, section 5.4, Tables 5.5/5.6) and its
// inverse. One deviation: a motion whose direction lies behind the start heading is written with
// a negative translation and rot1 within [-pi/2, pi/2], so that reversing is not modelled as a
// half turn (which would blow up the alpha1 rotation noise).
#pragma once

#include "core/common/Pose2D.h"

namespace rgnav {

struct OdometryMotion {
  double rot1 = 0.0;   // rad: turn towards the direction of travel
  double trans = 0.0;  // m: signed straight-line distance
  double rot2 = 0.0;   // rad: turn to the final heading
};

// Translations shorter than this are treated as pure rotations (rot1 = 0).
inline constexpr double kMinOdometryTranslation = 1e-6;  // m

OdometryMotion decomposeMotion(const Pose2D& from, const Pose2D& to);
Pose2D applyMotion(const Pose2D& from, const OdometryMotion& motion);

}  // namespace rgnav
