// DriveChain: what the Collision Avoidance hands the Low-Level Drive: a chain of trajectory
// segments in the odometry frame, the speed the robot has at its start, the time (on the
// odometry clock: the Base's odometry stamps) at which the reference passes the chain's start,
// and the chain's own top speed if lower than the robot's (TimedTrajectory's cruise speed).
// A chain always ends at a standstill: if no newer chain replaces it, the robot stops at its end,
// where the Collision Avoidance checked it could.
#pragma once

#include <cstdint>
#include <limits>

#include "core/common/SensorData.h"
#include "core/nav/motion/TrajectoryChain.h"

namespace rgnav {

struct DriveChain {
  std::uint64_t id = 0;     // > 0, increasing per sender
  TrajectoryChain chain;    // odometry frame
  double startSpeed = 0.0;  // m/s at the chain's start
  Timestamp startTime = 0.0;  // odometry clock
  double cruiseSpeed = 0.0;   // m/s, braked down to from a faster start; 0: the robot's top speed

  // The cruise speed for TimedTrajectory (infinite for 0).
  double cruiseOrUnlimited() const { return cruiseSpeed > 0.0 ? cruiseSpeed : std::numeric_limits<double>::infinity(); }
};

}  // namespace rgnav
