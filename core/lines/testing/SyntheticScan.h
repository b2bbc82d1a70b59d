// Test helpers: laser scans of known walls by ray casting, with optional Gaussian range noise,
// and the walls of a box.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "core/common/SensorData.h"

namespace rgnav::testing {

struct Wall {
  Eigen::Vector2d a, b;
};

struct ScanSpec {
  std::size_t beams = 361;
  double startAngleRad = -M_PI / 2;
  double incrementRad = M_PI / 360;
  double maxRangeM = 30.0;
  double noiseSigmaM = 0.0;
  unsigned seed = 1;
};

// A scan taken by a sensor at `sensorPose` (also stored as the scan's sensorPose and odometry):
// the nearest wall along each beam, +inf where no wall is within maxRangeM.
LaserScan syntheticScan(const std::vector<Wall>& walls, const Pose2D& sensorPose, const ScanSpec& spec = {});

// The four walls of a box centred at `center`, turned by thetaRad, length along its x-axis.
std::vector<Wall> boxWalls(const Eigen::Vector2d& center, double thetaRad, double lengthM, double widthM);

}  // namespace rgnav::testing
