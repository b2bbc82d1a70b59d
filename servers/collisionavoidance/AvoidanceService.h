// AvoidanceService: the Collision Avoidance module's work behind its servant (thesis 5.5.3). One
// thread follows the Laser's scans (InputFollower.h): every scan goes into the LaserObstacleMap;
// with the newest scan and the Base's newest odometry reading the core CollisionAvoidance decides
// (keep the chain, drive a new one, wait, blocked, goal reached) and new chains go to the
// Low-Level Drive. Drives come from the servant: driveTo asks the PathPlanning module for a plan
// from where the robot stands (map frame, MapFrame.h) and drives its targets; followTargets
// drives given targets. When the core finds the way blocked, a drive to a goal asks for a new
// plan: if the robot stands near a gateway crossing of its plan, the gateway is reported as a
// blocked door first (replanDoorBlocked: its learned cost rises, thesis 5.4; a gateway that is no
// door is refused by the planner and just planned around), then the goal is planned again from
// where the robot stands. A drive found blocked five times in a row within half a metre of where
// it was blocked before fails (its plans lead nowhere, e.g. to a goal beside furniture the map
// does not hold; the caller chooses another goal). Given targets that are blocked end the drive
// failed.
// Safety in motion (DESIGN.md): every chain ends at a standstill the core checked, so a killed
// module leaves the Low-Level Drive to finish or stop its chain; a restarted module first brakes
// the robot to a standstill (LowLevelDrive::stop) before it plans from where it stands. Chain IDs
// continue above the Low-Level Drive's last accepted one (read at start), so the drive accepts
// the chains of a restarted module.
// State survives: the drive is checkpointed (DriveCheckpoint.h) whenever it starts, gets a plan,
// or ends, and resumed after a restart. Request IDs: a repeated driveTo/followTargets with the
// drive's request answers its status and changes nothing.
// The map frame comes from the pose source (MapFrameSource.h); a drive waits until it is known.
// Health: scans, frame_refreshes, chains_sent, chains_refused, plans, replans, doors_reported, drives.
#pragma once

#include <chrono>
#include <mutex>
#include <optional>
#include <string>

#include "clientlibs/base/BaseClient.h"
#include "clientlibs/laser/LaserClient.h"
#include "clientlibs/lowleveldrive/LowLevelDriveClient.h"
#include "clientlibs/pathplanning/PathPlanningClient.h"
#include "core/nav/avoidance/CollisionAvoidance.h"
#include "core/nav/avoidance/DriveProgress.h"
#include "core/nav/avoidance/LaserObstacleMap.h"
#include "servers/collisionavoidance/DriveCheckpoint.h"
#include "servers/collisionavoidance/MapFrameSource.h"
#include "servers/common/CheckpointRetry.h"
#include "servers/common/InputFollower.h"
#include "servers/common/ModuleHealth.h"

namespace rgnav {

struct AvoidanceServiceOptions {
  PoseSource poseSource = PoseSource::Odometry;
  std::string laserObject = "Laser";
  std::string baseObject = "Base";
  std::string truthObject = "GroundTruth";
  std::string scanMapperObject = "ScanMapper";
  std::string localizationObject = "Localization";
  std::string driveObject = "LowLevelDrive";
  std::string plannerObject = "PathPlanning";
  std::string checkpointFile;  // empty: no checkpoints
  Footprint footprint = Footprint::disk(0.25);
  bool trace = false;  // log every decision but "keep" (stderr: the module's log)
};

class AvoidanceService {
 public:
  // Loads the checkpoint if there is one (FormatError if it is damaged). Contacts no module yet.
  AvoidanceService(const CollisionAvoidanceConfig& config, const ClientSettings& settings,
                   AvoidanceServiceOptions options, ModuleHealth& health);

  void start() { follower_.start(); }
  void stop() { follower_.stop(); }

  // InvalidArgumentError for a request ID 0, a goal or target that is not finite, no targets.
  DriveProgress driveTo(std::uint64_t request, const PlanGoal& goal);
  DriveProgress followTargets(std::uint64_t request, std::vector<TargetPose> targets);
  void cancel();
  DriveProgress status();

 private:
  bool step();
  std::string skipScan();
  RobotState robotState();
  void prepare();                                  // the core and the chain IDs, once
  DriveRecord takeDrive(std::uint64_t& generation);  // a copy, and a cancel owed
  bool current(std::uint64_t generation);          // under lock: the drive is still that one
  void plan(const DriveRecord& drive, std::uint64_t generation, const Pose2D& here);
  void decide(const DriveRecord& drive, std::uint64_t generation, const RobotState& state);
  void send(DriveChain chain);
  void traceDecision(const RobotState& state, const AvoidanceDecision& decision) const;
  void setCoreTargets(const std::vector<TargetPose>& targets);
  void followFrameDrift(const Pose2D& robot);  // robot: odometry frame
  void record(std::uint64_t generation, DrivePhase phase, const std::string& reason = {});
  void checkpoint();                               // under lock

  CollisionAvoidanceConfig config_;
  AvoidanceServiceOptions options_;
  ModuleHealth& health_;
  LaserClient laser_;
  BaseClient base_;
  LowLevelDriveClient lld_;
  PathPlanningClient planner_;

  // The follower's own (one thread).
  LaserObstacleMap obstacles_;
  std::optional<CollisionAvoidance> core_;
  DataId lastScan_ = 0;
  std::chrono::steady_clock::time_point stateWall_;  // when the latest odometry reading was read
  double stateStamp_ = 0.0;                          // its stamp (odometry clock)
  std::uint64_t chainBase_ = 0;
  std::uint64_t appliedGeneration_ = 0;
  bool settled_ = false;    // the robot stood still once since the start
  bool following_ = false;  // reading scans (a drive is active)
  MapFrameSource frameSource_;
  Pose2D mapFromOdometry_;  // the frame's latest answer
  Pose2D targetsFrame_;   // mapFromOdometry_ when the core's targets were converted
  double targetsFrameStamp_ = 0.0;
  std::optional<PlanRecord> lastPlan_;
  std::optional<Pose2D> blockedAt_;  // map frame: where the way was found blocked
  std::optional<Pose2D> lastBlock_;  // ... the last time, kept over plans
  std::uint32_t blocksInPlace_ = 0;  // blocks in a row near each other

  std::mutex mutex_;  // guards what follows (servant threads and the follower)
  DriveRecord drive_;
  std::uint64_t generation_ = 1;  // changes with every new drive and cancel
  bool stopOwed_ = false;
  CheckpointRetry retry_;
  InputFollower follower_;
};

}  // namespace rgnav
