// TrackingRun: the closed loop of one chain: odometry -> drive tick -> robot command, then the
// simulation advances by the loop clock's period.
#include "tests/eval/tracking/TrackingRun.h"

#include <algorithm>
#include <cmath>
#include <deque>

#include "core/sim/motion/DiffDriveRobot.h"

namespace rgnav {

namespace {

// A free grid covering the chain with 2 m to spare.
OccupancyGrid freeGridAround(const TrajectoryChain& chain) {
  double minX = 0.0, maxX = 0.0, minY = 0.0, maxY = 0.0;
  for (double s = 0.0; s <= chain.length(); s += 0.05) {
    const Pose2D p = chain.poseAt(s);
    minX = std::min(minX, p.x);
    maxX = std::max(maxX, p.x);
    minY = std::min(minY, p.y);
    maxY = std::max(maxY, p.y);
  }
  const double resolution = 0.1, margin = 2.0;
  return OccupancyGrid(static_cast<int>((maxX - minX + 2.0 * margin) / resolution) + 1,
                       static_cast<int>((maxY - minY + 2.0 * margin) / resolution) + 1, resolution,
                       {minX - margin, minY - margin});
}

}  // namespace

TrackingResult runTracking(const TrackingCase& trackingCase, LowLevelDriveConfig config, LoopClock& clock,
                           std::uint64_t& odometryId, int commandDelayTicks) {
  config.limits.maxVelocity = trackingCase.maxVelocity;
  config.commandDelayTicks = commandDelayTicks;
  LowLevelDrive drive(config);
  const OccupancyGrid grid = freeGridAround(trackingCase.chain);
  DiffDriveRobot robot(DiffDriveConfig{}, trackingCase.chain.start());
  TrackingResult result;
  result.predictedSeconds = TimedTrajectory(trackingCase.chain, referenceLimits(config)).duration();
  const double start = clock.now();
  drive.setChain({1, trackingCase.chain, 0.0, start});
  std::deque<VelocityCommand> inFlight(static_cast<std::size_t>(commandDelayTicks));
  double squares = 0.0;
  std::size_t samples = 0;
  while (clock.now() - start <= 2.0 * result.predictedSeconds + 5.0) {
    const double now = clock.now();
    const OdometryReading reading{++odometryId, now, robot.pose(), robot.velocity().translational,
                                  robot.velocity().rotational};
    inFlight.push_back(drive.tick(reading, now));
    robot.command(inFlight.front());
    inFlight.pop_front();
    const DriveStatus status = drive.status();
    if (status.chainFinished) {
      result.finished = true;
      result.realSeconds = now - start;
      break;
    }
    if (status.state == DriveState::Tracking) {
      squares += status.lateralError * status.lateralError;
      ++samples;
      result.maxLateral = std::max(result.maxLateral, std::abs(status.lateralError));
    }
    robot.step(clock.next(), grid);
  }
  result.rmsLateral = samples ? std::sqrt(squares / samples) : 0.0;
  const Pose2D error = between(trackingCase.chain.end(), robot.pose());
  result.finalPositionError = std::hypot(error.x, error.y);
  result.finalYawError = std::abs(error.theta);
  return result;
}

}  // namespace rgnav
