// Simulation: one simulated robot in a world (issue "Simulator driver"): differential-drive
// kinematics with collisions, odometry with the odometry motion model's noise and drift, and a
// SICK-like laser, advanced in fixed steps. Deterministic: the same world, configuration, seed
// and commands give the same scans and odometry, bit for bit. Time is simulated time; the
// caller decides how it relates to the wall clock (real time or lock-step).
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "core/common/SensorData.h"
#include "core/raster/OccupancyGrid.h"
#include "core/sim/motion/DiffDriveRobot.h"
#include "core/sim/motion/OdometryNoiseModel.h"
#include "core/sim/world/LaserModel.h"
#include "core/sim/world/Raycaster.h"

namespace rgnav {

struct SimulationConfig {
  DiffDriveConfig robot;
  OdometryNoiseConfig odometry;
  LaserConfig laser;
  double stepSeconds = 0.05;  // one kinematics step; an odometry reading per step (20 Hz)
  int stepsPerScan = 2;       // a scan every second step (10 Hz)
  std::uint64_t seed = 1;
};

// Throws ConfigError for a non-positive step or scan interval (and as the parts do).
void validate(const SimulationConfig& config);

struct SimulationStep {
  OdometryReading odometry;
  std::optional<LaserScan> scan;  // on scan steps
  Pose2D truePose;
  bool collided = false;
};

class Simulation {
 public:
  // Keeps a reference to `world`, which must outlive the simulation. Throws InvalidArgumentError
  // if the robot's footprint at the start pose overlaps a blocked cell.
  Simulation(const OccupancyGrid& world, const SimulationConfig& config, const Pose2D& start, Timestamp startTime = 0.0);

  // Target velocities, held until the next command.
  void command(const VelocityCommand& target) { robot_.command(target); }
  SimulationStep step();

  const Pose2D& truePose() const { return robot_.pose(); }
  const Pose2D& odometryPose() const { return odometryPose_; }
  Timestamp time() const { return time_; }
  std::uint64_t collisions() const { return collisions_; }
  const SimulationConfig& config() const { return config_; }
  // True pose of the robot when scan `id` was taken; NotAvailableError for an unknown ID.
  Pose2D truePoseOfScan(DataId id) const;

 private:
  const OccupancyGrid& world_;
  SimulationConfig config_;
  Raycaster raycaster_;
  LaserModel laser_;
  DiffDriveRobot robot_;
  OdometryNoiseModel odometryNoise_;
  std::mt19937_64 laserRng_;
  Pose2D odometryPose_;
  Timestamp time_;
  std::uint64_t steps_ = 0;
  std::uint64_t collisions_ = 0;
  DataId nextOdometryId_ = 1;
  std::vector<Pose2D> scanTruePoses_;  // index = scan ID - 1
};

}  // namespace rgnav
