// odometryInformation: the information matrix of an odometry motion under a simple error model
// whose standard deviations grow linearly with distance travelled and angle turned (the motion
// model of Thrun et al., Probabilistic Robotics 5.4, with standard deviations rather than
// variances proportional to the motion). Used as the prior of local registration and for
// keyframes that could not be registered.
#pragma once

#include <Eigen/Core>

#include "core/common/Pose2D.h"
#include "core/slam/SlamConfig.h"

namespace rgnav {

// Information (x, y, theta) of the pose reached by `motion`; the translational part is isotropic,
// so it holds in any frame.
Eigen::Matrix3d odometryInformation(const Pose2D& motion, const OdometryModelConfig& config);

}  // namespace rgnav
