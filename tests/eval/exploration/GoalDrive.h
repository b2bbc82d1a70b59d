// GoalDrive: a drive to a planned goal in process, as the Collision Avoidance module drives one
// (servers/collisionavoidance AvoidanceService.h, thesis 5.4 and 5.5.3) but without its server:
// the goal is planned with a RoutePlanner from the robot's map pose, the plan's targets go to the
// CollisionAvoidance core converted into the odometry frame (MapFrame.h: mapFromOdometry =
// corrected ∘ odometry⁻¹ of the latest scan), and the core decides on every scan. Where the
// odometry drifts against the map frame the targets still ahead are converted again (checked every
// kFrameCheckS while more than kFrameSettledM are left; near the goal a moved goal would come too
// late to brake for). Outcome: GoalReached -> Reached; Blocked -> planned once more from where the
// robot stands, blocked again (or no path) -> Failed. Unlike the module, a blocked door is not
// reported to the planner (the in-process planner learns no door costs).
#pragma once

#include <optional>
#include <string>

#include "core/nav/avoidance/CollisionAvoidance.h"
#include "core/nav/planning/RoutePlanner.h"

namespace rgnav {

enum class GoalDriveState { Idle, Driving, Reached, Failed };

class GoalDrive {
 public:
  static constexpr double kFrameCheckS = 2.0;
  static constexpr double kFrameDriftM = 0.1;
  static constexpr double kFrameDriftRad = 0.03;
  static constexpr double kFrameSettledM = 3.0;
  static constexpr std::size_t kReplans = 1;  // plans after a block before the drive fails

  // Throws ConfigError for a bad configuration, footprint or limits.
  GoalDrive(const CollisionAvoidanceConfig& config, const Footprint& footprint, const MotionLimits& limits);

  // A new drive from `here` (map frame) to `goal`, planned at once (Failed if there is no path).
  void start(const PlanGoal& goal, const RoutePlanner& planner, const Pose2D& here, const Pose2D& mapFromOdometry);
  // Ends the drive: the chain being driven is finished, no new one follows.
  void cancel();

  // The decision on one scan: the robot's state (odometry frame), the obstacle grid, where the
  // odometry frame lies in the map frame now, and the planner for a new plan after a block. Not
  // driving: no decision (Keep).
  AvoidanceDecision update(const RobotState& state, const ObstacleGrid& grid, const Pose2D& mapFromOdometry,
                           const RoutePlanner& planner);

  GoalDriveState state() const { return state_; }
  const std::string& reason() const { return reason_; }  // why it failed
  const std::optional<Plan>& plan() const { return plan_; }  // the latest plan of this drive

 private:
  void planFrom(const Pose2D& here, const RoutePlanner& planner, const Pose2D& mapFromOdometry);
  // The plan's last `left` targets (those not passed yet) to the core, converted with the frame now.
  void convertTargets(std::size_t left, const Pose2D& mapFromOdometry);
  void followFrame(const RobotState& state, const Pose2D& mapFromOdometry);

  CollisionAvoidance core_;
  GoalDriveState state_ = GoalDriveState::Idle;
  std::string reason_;
  PlanGoal goal_;
  std::optional<Plan> plan_;
  std::size_t replans_ = 0;
  Pose2D targetsFrame_;  // the mapFromOdometry the core's targets were converted with
  double frameCheckedAt_ = 0.0;
};

}  // namespace rgnav
