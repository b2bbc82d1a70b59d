// LaserModel: a simulated SICK LMS 200-like laser range finder (thesis 5: a 180 degree SICK LMS
// 220 facing forward about 0.40 m above the floor). Beams span the field of view including both
// ends (181 at 1 degree, 361 at 0.5 degree), starting at -fov/2 (the robot's right). Each range
// gets Gaussian noise; a dropout is a beam without return. Ranges follow REP 117 (SensorData.h):
// +inf for no return within maxRange. Beams see the world grid and round obstacles beside it
// (people, DiskObstacle.h).
#pragma once

#include <cmath>
#include <cstddef>
#include <random>
#include <span>

#include "core/common/SensorData.h"
#include "core/sim/world/DiskObstacle.h"
#include "core/sim/world/Raycaster.h"

namespace rgnav {

struct LaserConfig {
  double fieldOfView = M_PI;                 // rad
  double angularResolution = M_PI / 180.0;  // rad; the LMS offers 1 and 0.5 degrees
  double maxRange = 30.0;        // m; LMS 200: 80 m at best, 30 m on dark (10 %) surfaces
  double mountingHeight = 0.40;  // m above the floor: the plane rasterize() cuts the world at
  double forwardOffset = 0.0;    // m ahead of the robot centre along its heading
  double rangeNoiseSigma = 0.01;     // m, standard deviation of the Gaussian range noise
  double dropoutProbability = 0.0;   // per beam
};

class LaserModel {
 public:
  // Throws InvalidArgumentError for non-positive sizes, a field of view that is not a whole
  // number of steps (or above 2 pi), negative noise or a probability outside [0, 1].
  explicit LaserModel(const LaserConfig& config);

  const LaserConfig& config() const { return config_; }
  std::size_t beamCount() const { return beamCount_; }
  double startAngle() const { return -config_.fieldOfView / 2.0; }
  // The laser's pose in the world for a robot pose.
  Pose2D laserPose(const Pose2D& robotPose) const;

  // A scan taken at the robot's true pose, stamped with the odometry pose it is reported at.
  // sensorPose is the true laser pose. Draws from `rng` in a fixed order, so the same seed
  // gives the same scans. `obstacles` are seen where they are nearer than the grid.
  LaserScan simulate(const Pose2D& robotTruePose, const Pose2D& odometryPose, DataId id, Timestamp stamp,
                     const Raycaster& raycaster, std::mt19937_64& rng,
                     std::span<const DiskObstacle> obstacles = {}) const;

 private:
  LaserConfig config_;
  std::size_t beamCount_;
};

}  // namespace rgnav
