// Diagonal odometry information from the linear error model.
#include "core/slam/OdometryModel.h"

#include <cmath>

namespace rgnav {

Eigen::Matrix3d odometryInformation(const Pose2D& motion, const OdometryModelConfig& config) {
  const double distance = std::hypot(motion.x, motion.y);
  const double sigmaTranslation = config.minTranslation + config.translationPerMetre * distance;
  const double sigmaRotation =
      config.minRotation + config.rotationPerRadian * std::abs(motion.theta) + config.rotationPerMetre * distance;
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  information(0, 0) = information(1, 1) = 1.0 / (sigmaTranslation * sigmaTranslation);
  information(2, 2) = 1.0 / (sigmaRotation * sigmaRotation);
  return information;
}

}  // namespace rgnav
