// MaplessNavigator: driving to a goal with nothing but the laser (the BARN benchmark; later
// exploration): each scan goes into the LaserObstacleMap; GoalSeeking plans targets on it every
// goal_seeking.replan_period_s and at once when the Collision Avoidance reports it is blocked,
// each time blocked with a wider inflation (by kBlockedWidening, up to the footprint's
// circumradius: the way the planner found was too narrow for the exact footprint), back to the
// configured one once the robot has come a metre closer to the goal; the Collision Avoidance
// decides on the scan's grid. The caller hands the decision's chain to the Low-Level Drive.
// Everything in the odometry frame. The goal seeking stands in for thesis 5.4's planning on the
// RG map, the rest is the Collision Avoidance of 5.5.3.
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

  static constexpr double kBlockedWidening = 0.05;  // m per block

  void setGoal(WorldPoint goal);
  // One scan and the robot's state at its stamp.
  AvoidanceDecision onScan(const LaserScan& scan, const RobotState& state);

  const LaserObstacleMap& obstacleMap() const { return map_; }
  const CollisionAvoidance& avoidance() const { return avoidance_; }

 private:
  GoalSeekingConfig seekingConfig_;
  double maxWidening_;
  LaserObstacleMap map_;
  GoalSeeking seeking_;
  CollisionAvoidance avoidance_;
  std::optional<WorldPoint> goal_;
  std::optional<Timestamp> lastSeek_;
  bool seekNow_ = true;
  double widening_ = 0.0;       // m added to the planner's inflation after blocks
  double closestToGoal_ = 0.0;  // m, since the last block
};

}  // namespace rgnav
