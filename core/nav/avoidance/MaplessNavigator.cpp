// Laser-only goal navigation (see MaplessNavigator.h).
#include "core/nav/avoidance/MaplessNavigator.h"

#include <algorithm>
#include <cmath>

namespace rgnav {

MaplessNavigator::MaplessNavigator(const CollisionAvoidanceConfig& config, const Footprint& footprint,
                                   const MotionLimits& limits)
    : seekingConfig_(config.goalSeeking),
      maxWidening_(std::max(0.0, footprint.circumradius() - footprint.inscribedRadius())),
      map_(config.obstacleMap),
      seeking_(config.goalSeeking, footprint),
      avoidance_(config, footprint, limits) {}

void MaplessNavigator::setGoal(WorldPoint goal) {
  goal_ = goal;
  seekNow_ = true;
}

AvoidanceDecision MaplessNavigator::onScan(const LaserScan& scan, const RobotState& state) {
  map_.add(scan);
  const ObstacleGrid grid = map_.grid();
  if (goal_) {
    const double toGoal = std::hypot(goal_->x - state.pose.x, goal_->y - state.pose.y);
    if (widening_ > 0.0 && toGoal < closestToGoal_ - 1.0) widening_ = 0.0;
    if (widening_ == 0.0) closestToGoal_ = toGoal;
  }
  if (goal_ && (seekNow_ || !lastSeek_ || state.stamp - *lastSeek_ >= seekingConfig_.replanPeriodS)) {
    if (auto targets = seeking_.plan(grid.cells, state.pose, *goal_, widening_))
      avoidance_.setTargets(std::move(*targets));
    lastSeek_ = state.stamp;
    seekNow_ = false;
  }
  AvoidanceDecision decision = avoidance_.update(state, std::span(&grid, 1));
  if (decision.action == AvoidanceAction::Blocked) {
    seekNow_ = true;
    widening_ = std::min(widening_ + kBlockedWidening, maxWidening_);
  }
  if (decision.action == AvoidanceAction::GoalReached) goal_.reset();
  return decision;
}

}  // namespace rgnav
