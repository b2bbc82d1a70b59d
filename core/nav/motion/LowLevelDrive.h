// LowLevelDrive: the Low-Level Drive of thesis 5.5.3 without its server: it tracks the reference
// that moves along the current DriveChain's TimedTrajectory with the PostureController's
// Lyapunov-stable feedback law, one velocity command per tick (20 Hz in the module). It stops the
// robot at the chain's end; it brakes (within the limits) to a standstill when it loses its
// odometry input (no new reading for odometryTimeout) and when it has no chain. A newer chain
// replaces the current one at once (the Collision Avoidance plans it to continue from where the
// reference will be at its startTime).
// States: Idle (standing, no chain) -> setChain -> Tracking (the reference moves along the chain
// on the odometry clock; feed-forward speeds are the reference's mean over the next tick, as the
// base holds a command for one tick) -> Settling (the reference stands at the chain's end; the
// robot creeps onto the end pose until within 1 cm and 0.5 deg at rest, or for at most 3 s) ->
// Idle with chainFinished (after 3 s short of the end: Idle without). Odometry loss or stop():
// Braking (the chain is dropped; speeds fall along the current curvature at the deceleration
// limits) -> Idle. Every command keeps within the MotionLimits, including their accelerations
// from the previous command.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string>

#include "core/common/SensorData.h"
#include "core/common/VelocityCommand.h"
#include "core/nav/motion/DriveChain.h"
#include "core/nav/motion/PostureController.h"
#include "core/nav/motion/TimedTrajectory.h"

namespace rgnav {

struct LowLevelDriveConfig {
  MotionLimits limits;
  PostureGains gains;
  double periodSeconds = 0.05;          // one tick
  double odometryTimeoutSeconds = 0.3;  // no newer reading for this long (wall time): brake
  // Ticks between an odometry reading and the base acting on the command computed from it
  // (0-5). The drive predicts the robot's pose over the commands still in flight and tracks
  // the reference that many ticks ahead (a Smith-predictor-like compensation of the delay).
  int commandDelayTicks = 0;
  // The reference accelerates, brakes and turns up at (1 - referenceMargin) times the limits'
  // accelerations, so that the feedback has room within the full limits to catch up and to stop
  // without overshooting (0 to 0.5).
  double referenceMargin = 0.1;
};

// The limits the drive's reference moves within (see referenceMargin): the predicted time of a
// chain is TimedTrajectory(chain, referenceLimits(config), startSpeed).duration(). A chain these
// cannot time (e.g. a stop planned just long enough at the full deceleration) is driven at the
// full limits instead.
MotionLimits referenceLimits(const LowLevelDriveConfig& config);

enum class DriveState { Idle, Tracking, Settling, Braking };
std::string toString(DriveState state);

struct DriveStatus {
  DriveState state = DriveState::Idle;
  std::uint64_t chainId = 0;      // the chain being driven (or last driven); 0: none yet
  double progress = 0.0;          // m along it (the reference's arc length)
  double remainingSeconds = 0.0;  // predicted time to its end
  Pose2D reference;               // where the robot should be now
  double lateralError = 0.0;      // m, robot to reference, perpendicular to its heading
  bool chainFinished = false;     // the robot reached the chain's end and stands
};

class LowLevelDrive {
 public:
  // Throws ConfigError for bad limits, gains or periods.
  explicit LowLevelDrive(const LowLevelDriveConfig& config);

  // Replaces the current chain (InvalidArgumentError for an id not above the last one, or a
  // chain the limits cannot drive from its start speed to a standstill).
  void setChain(const DriveChain& chain);
  // Brakes to a standstill now (the chain is dropped).
  void stop();

  // One control step. `latest`: the newest odometry reading (pose in the odometry frame, stamp
  // on the odometry clock); `wallSeconds`: a monotonic wall clock, for the odometry timeout.
  VelocityCommand tick(const std::optional<OdometryReading>& latest, double wallSeconds);

  DriveStatus status() const;

 private:
  TimedTrajectory timedWithMargin(const DriveChain& chain) const;
  VelocityCommand track(const OdometryReading& reading);
  VelocityCommand settle(const OdometryReading& reading, double wallSeconds);
  VelocityCommand brake() const;
  VelocityCommand rateLimited(const VelocityCommand& wanted) const;
  void dropChain(DriveState next);

  LowLevelDriveConfig config_;
  PostureController controller_;
  std::optional<DriveChain> chain_;
  std::optional<TimedTrajectory> timed_;
  std::uint64_t lastChainId_ = 0;
  VelocityCommand lastCommand_;
  std::optional<OdometryReading> lastReading_;
  double lastReadingWall_ = 0.0;
  std::deque<VelocityCommand> inFlight_;  // the last commandDelayTicks commands, oldest first
  double settleStartWall_ = 0.0;
  DriveStatus status_;
};

}  // namespace rgnav
