// MaplessNavigator: driving to a goal with nothing but the laser (the BARN benchmark; later
// exploration): each scan goes into the LaserObstacleMap; GoalSeeking plans targets on it every
// goal_seeking.replan_period_s and at once when the Collision Avoidance reports it is blocked;
// the Collision Avoidance decides on the scan's grid. The caller hands the decision's chain to
// the Low-Level Drive. Everything in the odometry frame.
#pragma once

#include <optional>

#include "core/nav/avoidance/CollisionAvoidance.h"
#include "core/nav/avoidance/GoalSeeking.h"
#include "core/nav/avoidance/LaserObstacleMap.h"

namespace rgnav {

class MaplessNavigator {
 public:
  // Throws ConfigError for a bad configuration, footprint or limits.
  MaplessNavigator(const CollisionAvoidanceConfig& config, const Footprint& footprint, const MotionLimits& limits);

  void setGoal(WorldPoint goal);
  // One scan and the robot's state at its stamp.
  AvoidanceDecision onScan(const LaserScan& scan, const RobotState& state);

  const LaserObstacleMap& obstacleMap() const { return map_; }
  const CollisionAvoidance& avoidance() const { return avoidance_; }

 private:
  GoalSeekingConfig seekingConfig_;
  LaserObstacleMap map_;
  GoalSeeking seeking_;
  CollisionAvoidance avoidance_;
  std::optional<WorldPoint> goal_;
  std::optional<Timestamp> lastSeek_;
  bool seekNow_ = true;
};

}  // namespace rgnav
