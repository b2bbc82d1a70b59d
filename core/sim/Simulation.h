// Simulation: one simulated robot in a world (issue "Simulator driver"): differential-drive
// kinematics with collisions, odometry with the odometry motion model's noise and drift, and a
// SICK-like laser, advanced in fixed steps; optionally people walking through the world (issue
// "Motion": moving obstacles the laser sees and the robot can run into). Deterministic: the same
// world, configuration, seed and commands give the same scans, odometry and walks, bit for bit.
// Time is simulated time; the caller decides how it relates to the wall clock (real time or
// lock-step).
//
// In-process, lock-step use (the evaluations: no servers, no wall clock):
//   const LoadedWorld world = loadWorld("…/barn_000.yaml");            // LoadedWorld.h
//   SimulationConfig config = loadSimulationConfig("config/sim/jackal.yaml");
//   config.people.count = 8;                                           // or people: in the YAML
//   Simulation sim(world.grid, config, world.task->start);
//   while (sim.time() < 100.0) {
//     sim.command({v, w});                  // held until the next command (clamped, ramped)
//     const SimulationStep s = sim.step();  // stepSeconds on: s.odometry every step,
//     if (s.scan) { … }                     // s.scan every stepsPerScan steps, s.truePose
//   }
//   sim.truePose(); sim.odometryPose(); sim.people(); sim.robotCollisions(); sim.personBumps();
// A collision stops the robot at its last free pose (velocities and command zeroed); a person
// that would walk into the robot stops short of it and turns away.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <vector>

#include "core/common/SensorData.h"
#include "core/raster/OccupancyGrid.h"
#include "core/sim/motion/DiffDriveRobot.h"
#include "core/sim/motion/OdometryNoiseModel.h"
#include "core/sim/people/Crowd.h"
#include "core/sim/world/LaserModel.h"
#include "core/sim/world/Raycaster.h"

namespace rgnav {

struct SimulationConfig {
  DiffDriveConfig robot;
  OdometryNoiseConfig odometry;
  LaserConfig laser;
  PeopleConfig people;        // none by default
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
  bool collided = false;  // the robot drove into a wall or a person in this step
  bool bumped = false;    // a person walked into the robot in this step (people/ContactBlame.h)
};

class Simulation {
 public:
  // Keeps a reference to `world`, which must outlive the simulation. Throws InvalidArgumentError
  // if the robot's footprint at the start pose overlaps a blocked cell, or if there is no room
  // for the people away from the robot.
  Simulation(const OccupancyGrid& world, const SimulationConfig& config, const Pose2D& start, Timestamp startTime = 0.0);

  // Target velocities, held until the next command.
  void command(const VelocityCommand& target) { robot_.command(target); }
  SimulationStep step();

  const Pose2D& truePose() const { return robot_.pose(); }
  const VelocityCommand& trueVelocity() const { return robot_.velocity(); }
  const Pose2D& odometryPose() const { return odometryPose_; }
  Timestamp time() const { return time_; }
  // Steps in which the robot drove into something: a wall (grid cell) or a person, including a
  // person it touched with its outline moving towards them (people/ContactBlame.h). A robot
  // commanded on against an obstacle collides again in every step it is commanded so.
  std::uint64_t robotCollisions() const { return robotCollisions_; }
  // People who walked into the robot: it stood, drove away from them or passed them sideways
  // (each contact counted once).
  std::uint64_t personBumps() const { return personBumps_; }
  // Where the people are (empty without people).
  std::span<const Person> people() const;
  const SimulationConfig& config() const { return config_; }
  // True pose of the robot when scan `id` was taken; NotAvailableError for an unknown ID.
  Pose2D truePoseOfScan(DataId id) const;

 private:
  std::span<const DiskObstacle> peopleObstacles() const;

  const OccupancyGrid& world_;
  SimulationConfig config_;
  Raycaster raycaster_;
  LaserModel laser_;
  DiffDriveRobot robot_;
  OdometryNoiseModel odometryNoise_;
  std::mt19937_64 laserRng_;
  std::optional<Crowd> crowd_;
  Pose2D odometryPose_;
  Timestamp time_;
  std::uint64_t steps_ = 0;
  std::uint64_t robotCollisions_ = 0;
  std::uint64_t personBumps_ = 0;
  DataId nextOdometryId_ = 1;
  std::vector<Pose2D> scanTruePoses_;  // index = scan ID - 1
};

}  // namespace rgnav
