// TimedTrajectory: a trajectory chain with the fastest velocity profile the robot's limits allow
// (thesis 5.5.3: the time to traverse a chain is predicted): speed v(s) bounded by the top speed,
// the top rotational speed (|kappa| v), the lateral acceleration (kappa v^2), the rotational
// acceleration (|sharpness v^2 + kappa a|) and the (de)acceleration limits, from a given start
// speed to a given end speed (0: the chain ends at a standstill). Forward-backward passes over
// the arc length on a fine grid; time by integrating ds / v. stateAt(t) is the reference the
// Low-Level Drive tracks. At a curvature jump between segments (a chain that is only G1, e.g.
// joined by PoseJoins' clothoidJoin, or a turn on the spot as an arc of millimetre radius before a
// straight) the speed is capped so that the rotational speed's step v * |jump| is one the
// rotational acceleration makes up within one 50 ms control period: a spot turn slows its
// rotation before the straight, a G1 joint of jump 1/m is passed at about 8 cm/s, so
// curvature-continuous chains are the fast ones.
#pragma once

#include <limits>
#include <vector>

#include "core/nav/motion/MotionLimits.h"
#include "core/nav/motion/TrajectoryChain.h"

namespace rgnav {

// Where the reference is at one time: pose, arc length, speeds and acceleration.
struct ReferenceState {
  Pose2D pose;
  double s = 0.0;             // m along the chain
  double velocity = 0.0;      // m/s
  double rotational = 0.0;    // rad/s = velocity * curvature
  double acceleration = 0.0;  // m/s^2
};

class TimedTrajectory {
 public:
  TimedTrajectory() = default;
  // Throws InvalidArgumentError for an empty chain or a start speed above what the limits allow
  // at the chain's start, or if the chain is too short to reach `endSpeed` from `startSpeed`
  // (a start speed that cannot brake to the end speed within the chain). `cruiseSpeed`: a lower
  // top speed for this chain; a faster start brakes down to it at the deceleration limit.
  TimedTrajectory(TrajectoryChain chain, const MotionLimits& limits, double startSpeed = 0.0, double endSpeed = 0.0,
                  double cruiseSpeed = std::numeric_limits<double>::infinity());

  const TrajectoryChain& chain() const { return chain_; }
  double duration() const;       // s: the predicted time to drive the chain
  double startSpeed() const;
  double endSpeed() const;
  double cruiseSpeed() const { return cruiseSpeed_; }  // as given (infinite: none)
  // t in [0, duration()] (clamped): the reference at t seconds after the chain's start.
  ReferenceState stateAt(double t) const;
  // The time at which the reference reaches arc length s.
  double timeAt(double s) const;
  // The highest speed the profile allows at arc length s.
  double speedAt(double s) const;

 private:
  TrajectoryChain chain_;
  double cruiseSpeed_ = std::numeric_limits<double>::infinity();
  std::vector<double> s_;  // profile grid
  std::vector<double> v_;  // speed at s_
  std::vector<double> t_;  // time at s_
};

}  // namespace rgnav
