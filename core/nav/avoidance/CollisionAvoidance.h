// CollisionAvoidance: the Collision Avoidance Module's reasoning (thesis 5.5.3) without its
// server. Given the planner's target poses (odometry frame, 0.5-2 m apart), the robot's state and
// the obstacle grids, each update() decides:
//   Keep        the chain being driven is still free (re-checked against every new grid);
//   Drive       a new DriveChain: the best free candidate (ChainCandidates.h) scored by its
//               predicted time, the path left from its end to the goal and its clearance
//               (manoeuvres away from the path drive at most as fast as their tight turns can be
//               entered, so the robot can still turn into a door it comes by; chains passing
//               moving obstacles (the grids' moving layer: people) slow enough to stop before
//               they could reach the robot; held back so for 5 s, the robot takes them for
//               standing obstacles); it
//               starts where the reference of the current chain will be one planning latency
//               from now (startTime on the odometry clock) and ends at a standstill in checked
//               free space, so the robot stops safely if this module dies;
//   Wait        no chain is free: stand (the decision may carry a chain that brakes), retry;
//   Blocked     waited blockedWaitS without a free chain: the caller asks the planner for a new
//               plan (thesis 5.4: a blocked door raises its edge's cost) and sets new targets;
//               the next chain may then keep only escapeMarginM (a robot that stopped too close
//               to turn or go on gets out);
//   GoalReached standing within goalToleranceM of the last target.
// Every chain ends where the robot can turn on the spot (its circumscribed disk keeps the margin),
// since it cannot back out: a candidate that is not free to its end, or ends in a narrow place,
// is cut back to such a pose (and driven if the robot can stop there): it closes in and sees more.
// Deliberate differences to the thesis: no conic or elliptic segments (clothoids, arcs and
// straights join every pair of poses), and moving obstacles are handled by re-checking at the
// scan rate with a safety margin and by the speed cap near them, not by predicting their motion.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/nav/avoidance/ChainCandidates.h"
#include "core/nav/avoidance/CollisionAvoidanceConfig.h"
#include "core/nav/avoidance/ObstacleGrid.h"
#include "core/nav/avoidance/SweptFootprint.h"
#include "core/nav/grid/Footprint.h"
#include "core/nav/motion/DriveChain.h"
#include "core/nav/motion/MotionLimits.h"
#include "core/nav/motion/TimedTrajectory.h"

namespace rgnav {

struct RobotState {
  Timestamp stamp = 0.0;  // odometry clock
  Pose2D pose;            // odometry frame
  double velocity = 0.0;    // m/s
  double rotational = 0.0;  // rad/s
};

enum class AvoidanceAction { Keep, Drive, Wait, Blocked, GoalReached };
std::string toString(AvoidanceAction action);

struct AvoidanceDecision {
  AvoidanceAction action = AvoidanceAction::Keep;
  std::optional<DriveChain> chain;  // Drive; Wait when the robot must brake
  std::string reason;
  bool stopNow = false;  // Wait: no braking chain (none timed, or the robot creeps): the caller stops the drive at once
};

class CollisionAvoidance {
 public:
  // Throws ConfigError for a bad configuration, footprint or limits.
  CollisionAvoidance(const CollisionAvoidanceConfig& config, const Footprint& footprint, const MotionLimits& limits);

  // New targets (odometry frame; the goal last); an empty list stops at the current chain's end.
  void setTargets(std::vector<Pose2D> targets);
  const std::vector<Pose2D>& targets() const { return targets_; }

  // One decision for the state and the grids (at least one grid).
  AvoidanceDecision update(const RobotState& state, std::span<const ObstacleGrid> grids);

  // The chain last sent (nullopt before the first or after the goal).
  const std::optional<DriveChain>& currentChain() const { return current_; }

 private:
  struct Scored {
    Candidate candidate;
    TimedTrajectory timed;
    double cost = 0.0;
  };
  // Where the next chain starts: the state one planning latency ahead on the current chain (or
  // the robot, standing), the rest of the turn it is in (the lead, so that new chains do not
  // jump in curvature), and how much of the current chain is left from there.
  struct PlanStart {
    ChainStart state;
    TrajectoryChain lead;
    double onCurrent = 0.0;      // arc length of the start on the current chain
    double leftOnCurrent = 0.0;  // 0: the next chain starts at the robot, standing
  };

  PlanStart planStart(const RobotState& state) const;
  double margin() const;
  SweptCheckOptions checkOptions() const;
  bool currentStillFree(const RobotState& state, const ObstacleClearance& clearance) const;
  void dropPassedTargets(const Pose2D& from);
  double pathLeftFrom(const TrajectoryChain& chain) const;
  std::vector<Candidate> candidatesFrom(const PlanStart& start) const;
  std::optional<Scored> bestCandidate(const PlanStart& start, const ObstacleClearance& clearance,
                                      const ObstacleClearance& moving, bool patient) const;
  // The speed cap moving obstacles set on a chain (infinite: none, or out of patience).
  double peopleCap(const TrajectoryChain& chain, const ObstacleClearance& moving, bool patient) const;
  // How far moving obstacles are from the chain (clearance plus the arc length where it occurs;
  // infinite without moving obstacles).
  double movingGap(const TrajectoryChain& chain, const ObstacleClearance& moving) const;
  // The largest arc length up to `end` (in steps) where the robot could turn on the spot, or 0.
  double turnableUntil(const TrajectoryChain& chain, double end, const ObstacleClearance& clearance) const;
  // The speed up to which the manoeuvres' turns can be entered (rotational acceleration over
  // their sharpness).
  double manoeuvreSpeed() const;
  // The speed from which the robot stops before an obstacle `gap` ahead that comes towards it at
  // oncomingSpeedMps (both moving on while the robot reacts).
  double oncomingStopSpeed(double gap) const;
  double brakingDistance(double speed) const;
  std::optional<TimedTrajectory> brakingChain(const PlanStart& start) const;
  AvoidanceDecision send(const RobotState& state, TimedTrajectory timed, AvoidanceAction action, std::string reason);
  AvoidanceDecision wait(const RobotState& state, const PlanStart& start, bool currentFree);

  CollisionAvoidanceConfig config_;
  Footprint footprint_;
  MotionLimits limits_;
  std::vector<Pose2D> targets_;
  bool targetsChanged_ = false;
  std::optional<DriveChain> current_;
  std::optional<TimedTrajectory> currentTimed_;
  Timestamp lastPlan_ = 0.0;
  std::optional<Timestamp> waitingSince_;
  bool braking_ = false;  // the chain sent last brakes: no other until a free one
  bool escaping_ = false;  // blocked: the next chain may come as close as escapeMarginM
  std::optional<Timestamp> heldSince_;  // since then moving obstacles hold the robot back
  std::uint64_t nextId_ = 1;
};

}  // namespace rgnav
