// InProcessRobot: the whole robot of issue 29 in one process and in lock-step, for the exploration
// and task evaluations ("rgctl eval exploration", "rgctl eval tasks"): the simulator (no people)
// steps 20 times a simulated second; every scan goes, as the modules would get it (its sensor pose
// replaced by its odometry pose, nothing of the truth), through the mapping chain (MappingPipeline:
// SLAM -> gateway detection -> RG Mapping Kernel) and into the laser obstacle grid; every
// mapPeriodS the kernel's PlanningMap goes into the RoutePlanner; a GoalDrive decides on each scan
// and the Low-Level Drive commands the simulator on every step, as in the BARN run
// (tests/eval/barn/BarnRun.cpp: a chain reaches the drive at its start time). The robot's pose is
// the SLAM pose: the corrected pose of the latest scan carried on by the odometry since
// (mapFromOdometry = corrected ∘ odometry⁻¹ of that scan). Deterministic for a seed.
// The map frame is SLAM's, fixed at the first scan's odometry pose; the odometry starts at the
// true start pose, so it is the world frame up to the first scan's odometry noise
// (mapToWorld, as MappingRun.h places it).
// The current region's freespace grows with every scan without a kernel event; the RoutePlanner
// rebuilds the grid of a region whose summary changed, as in the PathPlanning module.
#pragma once

#include <optional>

#include "core/nav/avoidance/LaserObstacleMap.h"
#include "core/nav/motion/LowLevelDrive.h"
#include "core/sim/Simulation.h"
#include "tests/eval/exploration/GoalDrive.h"
#include "tests/eval/rooms/MappingPipeline.h"

namespace rgnav {

struct RobotSetup {
  SimulationConfig simulation;
  MappingPipelineConfig pipeline;
  RoutePlannerConfig planner;
  CollisionAvoidanceConfig avoidance;
  LowLevelDriveConfig drive;
  double mapPeriodS = 1.0;  // simulated seconds between planning maps
};

// The shipped configuration (config/sim/default.yaml, config/modules/*.yaml), the avoidance's
// laser offset and the drive's period taken from the simulator. Throws what the loaders throw.
RobotSetup shippedRobotSetup();

class InProcessRobot {
 public:
  // Keeps a reference to `world`. Throws ConfigError / InvalidArgumentError as the parts do.
  InProcessRobot(const OccupancyGrid& world, const RobotSetup& setup, const Pose2D& start,
                 std::optional<HmmClassifier> classifier);

  // One simulation step, as the simulator gave it (the scan with its true sensor pose).
  SimulationStep step();

  // A drive to `goal` from where the robot is now (planned at once).
  void driveTo(const PlanGoal& goal);
  void cancelDrive() { drive_.cancel(); }
  const GoalDrive& drive() const { return drive_; }

  Pose2D pose() const;  // map frame: the SLAM pose
  bool mapped() const { return !planner_.map().regions.empty(); }
  const RoutePlanner& planner() const { return planner_; }
  const RgMappingKernel& kernel() const { return pipeline_.kernel(); }
  RgMappingKernel& kernel() { return pipeline_.kernel(); }
  const Simulation& simulation() const { return sim_; }
  double time() const { return sim_.time(); }
  double pathM() const { return pathM_; }  // true distance driven
  // The map frame in the world frame (the first scan's true pose ∘ its corrected pose⁻¹).
  Pose2D mapToWorld() const;
  const RobotSetup& setup() const { return setup_; }
  // The kernel's map into the planner now (after naming, say); step() does so every mapPeriodS.
  void refreshMap();

 private:

  RobotSetup setup_;
  Simulation sim_;
  MappingPipeline pipeline_;
  LaserObstacleMap obstacles_;
  GoalDrive drive_;
  LowLevelDrive lowLevel_;
  RoutePlanner planner_;
  std::optional<DriveChain> pending_;
  Pose2D mapFromOdometry_;
  Pose2D lastTrue_;
  Pose2D firstTrue_;
  double mapAt_ = -1e9;
  double pathM_ = 0.0;
};

}  // namespace rgnav
