// TrackingRun: one chain of the tracking evaluation driven by the Low-Level Drive in the loop
// with the simulator's robot (core/sim/motion/DiffDriveRobot, no odometry noise: the odometry is
// the true pose, stamped with the simulated time), from a standstill at the chain's start until
// the drive reports the chain finished (or twice the predicted time plus 5 s have passed).
#pragma once

#include <cstdint>

#include "core/nav/motion/LowLevelDrive.h"
#include "tests/eval/tracking/LoopClock.h"
#include "tests/eval/tracking/TrackingSuite.h"

namespace rgnav {

struct TrackingResult {
  bool finished = false;
  double predictedSeconds = 0.0;  // the drive's velocity profile
  double realSeconds = 0.0;       // from the chain's start time to standing at its end
  double rmsLateral = 0.0;        // m, robot to the moving reference, across its heading
  double maxLateral = 0.0;
  double finalPositionError = 0.0;  // m, robot to the chain's end
  double finalYawError = 0.0;       // rad
};

// `config.limits.maxVelocity` is replaced by the case's top speed. `commandDelayTicks`: the robot
// receives each command that many ticks late (0: at once), and the drive is told so.
TrackingResult runTracking(const TrackingCase& trackingCase, LowLevelDriveConfig config, LoopClock& clock,
                           std::uint64_t& odometryId, int commandDelayTicks);

}  // namespace rgnav
