// DriveChain: what the Collision Avoidance hands the Low-Level Drive: a chain of trajectory
// segments in the odometry frame, the speed the robot has at its start, and the time (on the
// odometry clock: the Base's odometry stamps) at which the reference passes the chain's start.
// A chain always ends at a standstill: if no newer chain replaces it, the robot stops at its end,
// where the Collision Avoidance checked it could.
#pragma once

#include <cstdint>

#include "core/common/SensorData.h"
#include "core/nav/motion/TrajectoryChain.h"

namespace rgnav {

struct DriveChain {
  std::uint64_t id = 0;     // > 0, increasing per sender
  TrajectoryChain chain;    // odometry frame
  double startSpeed = 0.0;  // m/s at the chain's start
  Timestamp startTime = 0.0;  // odometry clock
};

}  // namespace rgnav
