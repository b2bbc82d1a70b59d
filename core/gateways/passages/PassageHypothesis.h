// PassageHypothesis: one narrow passage seen in one laser scan (thesis 4.2.1, figure 4.9): the
// two gateway points P_left and P_right, the width D_lr between them, the distance D_NP of the
// scanner to the passage along the line of sight and the aperture α_NP. The confidence is ours
// (the thesis has none): the share of the beams between the gateway points that reach beyond
// the gateway line into open space.
#pragma once

#include <Eigen/Core>

#include "core/common/SensorData.h"

namespace rgnav {

struct PassageHypothesis {
  DataId scanId = 0;
  Eigen::Vector2d left = Eigen::Vector2d::Zero();   // P_left, world frame (the larger bearing)
  Eigen::Vector2d right = Eigen::Vector2d::Zero();  // P_right, world frame
  double widthM = 0.0;               // D_lr
  double distanceM = 0.0;            // D_NP
  double apertureRad = 0.0;          // α_NP
  double viewingDirectionRad = 0.0;  // α_m, relative to the sensor heading
  double confidence = 0.0;           // in (0, 1]

  Eigen::Vector2d midpoint() const { return 0.5 * (left + right); }
};

}  // namespace rgnav
