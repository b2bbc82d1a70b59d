// A planned drive through the Collision Avoidance core; see GoalDrive.h.
#include "tests/eval/exploration/GoalDrive.h"

#include <cmath>

#include "core/nav/grid/PlanningErrors.h"
#include "servers/collisionavoidance/MapFrame.h"

namespace rgnav {

GoalDrive::GoalDrive(const CollisionAvoidanceConfig& config, const Footprint& footprint, const MotionLimits& limits)
    : core_(config, footprint, limits) {}

void GoalDrive::start(const PlanGoal& goal, const RoutePlanner& planner, const Pose2D& here,
                      const Pose2D& mapFromOdometry) {
  goal_ = goal;
  replans_ = 0;
  reason_.clear();
  plan_.reset();
  state_ = GoalDriveState::Driving;
  planFrom(here, planner, mapFromOdometry);
}

void GoalDrive::cancel() {
  core_.setTargets({});
  if (state_ == GoalDriveState::Driving) state_ = GoalDriveState::Idle;
}

void GoalDrive::planFrom(const Pose2D& here, const RoutePlanner& planner, const Pose2D& mapFromOdometry) {
  try {
    plan_ = planner.plan(here, goal_);
  } catch (const NoPathError& e) {
    reason_ = e.what();
    state_ = GoalDriveState::Failed;
    core_.setTargets({});
    return;
  }
  if (plan_->targets.empty()) {  // standing at the goal
    state_ = GoalDriveState::Reached;
    core_.setTargets({});
    return;
  }
  convertTargets(plan_->targets.size(), mapFromOdometry);
}

void GoalDrive::convertTargets(std::size_t left, const Pose2D& mapFromOdometry) {
  std::vector<Pose2D> targets;
  for (std::size_t i = plan_->targets.size() - std::min(left, plan_->targets.size()); i < plan_->targets.size(); ++i)
    targets.push_back(toOdometry(mapFromOdometry, plan_->targets[i].pose));
  core_.setTargets(std::move(targets));
  targetsFrame_ = mapFromOdometry;
}

void GoalDrive::followFrame(const RobotState& state, const Pose2D& mapFromOdometry) {
  if (state.stamp - frameCheckedAt_ < kFrameCheckS) return;
  frameCheckedAt_ = state.stamp;
  double left = 0.0;
  Pose2D from = state.pose;
  for (const Pose2D& t : core_.targets()) {
    left += std::hypot(t.x - from.x, t.y - from.y);
    from = t;
  }
  const Pose2D drift = between(targetsFrame_, mapFromOdometry);
  if (left < kFrameSettledM || (std::hypot(drift.x, drift.y) < kFrameDriftM && std::abs(drift.theta) < kFrameDriftRad))
    return;
  // The core drops targets from the front as it passes them: those left are the plan's last ones.
  convertTargets(core_.targets().size(), mapFromOdometry);
}

AvoidanceDecision GoalDrive::update(const RobotState& state, const ObstacleGrid& grid, const Pose2D& mapFromOdometry,
                                    const RoutePlanner& planner) {
  if (state_ != GoalDriveState::Driving) return {};
  followFrame(state, mapFromOdometry);
  AvoidanceDecision decision = core_.update(state, std::span<const ObstacleGrid>(&grid, 1));
  if (decision.action == AvoidanceAction::GoalReached) {
    state_ = GoalDriveState::Reached;
  } else if (decision.action == AvoidanceAction::Blocked) {
    if (replans_ >= kReplans) {
      reason_ = "blocked: " + decision.reason;
      state_ = GoalDriveState::Failed;
      core_.setTargets({});
    } else {
      ++replans_;
      planFrom(toMap(mapFromOdometry, state.pose), planner, mapFromOdometry);
    }
  }
  return decision;
}

}  // namespace rgnav
