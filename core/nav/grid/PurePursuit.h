// PurePursuit: a waypoint follower on a known pose; the simulator drives it on the true pose as its
// stand-in for a person with a joystick (Coulter, "Implementation of the Pure Pursuit Path Tracking
// Algorithm", CMU-RI-TR-92-01, 1992). The robot steers on the circle through the point one
// lookahead distance further along the path than its own projection (curvature 2 y / d^2 in the
// robot frame), keeps |w| within its limit by slowing down, and slows linearly before stops. Like a
// careful driver in tight places it stops at sharp corners (waypoints where the path turns by more
// than a corner angle), so the lookahead point never cuts across them, and turns on the spot
// whenever the lookahead point lies too far to the side, until it faces it. Reports when the final
// goal is reached.
#pragma once

#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/VelocityCommand.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

struct PurePursuitConfig {
  double lookahead = 0.4;                // m
  double maxTranslationalVelocity = 0.5; // m/s
  double maxRotationalVelocity = 1.0;    // rad/s
  double rotationGain = 2.0;             // 1/s: on-the-spot turn rate per radian of bearing
  double goalTolerance = 0.02;           // m; how close counts as at a corner or the goal
  double slowdownDistance = 1.0;         // m before a stop where the speed starts to fall
  double minApproachVelocity = 0.05;     // m/s; the speed the slowdown never goes below
  double cornerAngle = 0.35;             // rad; the path turning more than this is a stop
  double rotateInPlaceBearing = 0.35;    // rad; beyond this bearing the robot turns on the spot
  double alignedBearing = 0.05;          // rad; ... until the bearing is below this
};

// Throws ConfigError for non-positive values, a minimum approach velocity above the maximum, or
// bearings/angles outside (0, pi] with alignedBearing <= rotateInPlaceBearing.
void validate(const PurePursuitConfig& config);

class PurePursuit {
 public:
  // `path`: the waypoints in order, the final goal last. Throws InvalidArgumentError for an empty
  // path, ConfigError for a bad configuration.
  PurePursuit(const PurePursuitConfig& config, std::vector<WorldPoint> path);

  // The command for the robot at `pose`; advances the progress along the path (never backwards,
  // never past the next stop, and by at most two lookahead distances per call, so a path that
  // passes the same place twice is followed in order). Zero once the goal is reached.
  VelocityCommand command(const Pose2D& pose);

  bool reached() const { return reached_; }

 private:
  WorldPoint pointAt(double s) const;
  void project(WorldPoint p, double limit);

  PurePursuitConfig config_;
  std::vector<WorldPoint> path_;
  std::vector<double> arcLength_;  // arc length at each waypoint
  std::vector<std::size_t> stops_; // waypoints to stop at: sharp corners, then the goal
  std::size_t nextStop_ = 0;       // index into stops_
  double progress_ = 0.0;          // arc length of the robot's projection
  double offPath_ = 0.0;           // distance from the robot to its projection
  bool turning_ = false;           // turning on the spot
  bool reached_ = false;
};

}  // namespace rgnav
