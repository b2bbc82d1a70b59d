// LowLevelDrive: the state machine of the header around the PostureController.
#include "core/nav/motion/LowLevelDrive.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"

namespace rgnav {

namespace {

constexpr double kSettlePosition = 0.01;                 // m
constexpr double kSettleHeading = 0.5 * M_PI / 180.0;    // rad
constexpr double kSettleSpeed = 0.01;                    // m/s: standing
constexpr double kSettleTurnRate = 0.02;                 // rad/s: standing
constexpr double kSettleSeconds = 3.0;                   // then it stands where it is
constexpr double kCreepSpeed = 0.1;                      // m/s while settling
constexpr double kCreepTurnRate = 0.3;                   // rad/s while settling
constexpr double kCreepTurnGain = 2.0;                   // 1/s

double towards(double current, double wanted, double maxUp, double maxDown) {
  const bool speedingUp = std::abs(wanted) > std::abs(current) && wanted * current >= 0.0;
  const double step = speedingUp ? maxUp : maxDown;
  return current + std::clamp(wanted - current, -step, step);
}

// The pose after driving at the command's speeds for dt seconds (an arc; backwards for a negative
// translational speed).
Pose2D afterCommand(const Pose2D& p, const VelocityCommand& c, double dt) {
  const double distance = std::abs(c.translational) * dt;
  if (distance < 1e-12) return {p.x, p.y, normalizeAngle(p.theta + c.rotational * dt)};
  const double flip = c.translational < 0.0 ? M_PI : 0.0;
  Pose2D end = TrajectorySegment{{p.x, p.y, p.theta + flip}, distance, c.rotational * dt / distance, 0.0}.end();
  end.theta = normalizeAngle(end.theta - flip);
  return end;
}

}  // namespace

MotionLimits referenceLimits(const LowLevelDriveConfig& config) {
  MotionLimits limits = config.limits;
  const double keep = 1.0 - config.referenceMargin;
  limits.maxAcceleration *= keep;
  limits.maxDeceleration *= keep;
  limits.maxRotationalAcceleration *= keep;
  return limits;
}

std::string toString(DriveState state) {
  switch (state) {
    case DriveState::Idle: return "idle";
    case DriveState::Tracking: return "tracking";
    case DriveState::Settling: return "settling";
    case DriveState::Braking: return "braking";
  }
  return "unknown";
}

LowLevelDrive::LowLevelDrive(const LowLevelDriveConfig& config)
    : config_(config), controller_(config.gains, config.limits) {
  requirePositive(config_.periodSeconds, "low-level drive period");
  requirePositive(config_.odometryTimeoutSeconds, "low-level drive odometry timeout");
  if (config_.commandDelayTicks < 0 || config_.commandDelayTicks > 5) {
    throw ConfigError("low-level drive command delay must be 0 to 5 ticks");
  }
  if (!(config_.referenceMargin >= 0.0 && config_.referenceMargin <= 0.5)) {
    throw ConfigError("low-level drive reference margin must be 0 to 0.5");
  }
  inFlight_.assign(static_cast<std::size_t>(config_.commandDelayTicks), VelocityCommand{});
}

void LowLevelDrive::setChain(const DriveChain& chain) {
  if (chain.id <= lastChainId_) {
    throw InvalidArgumentError("low-level drive: chain id " + std::to_string(chain.id) +
                               " is not above the last one (" + std::to_string(lastChainId_) + ")");
  }
  TimedTrajectory timed = timedWithMargin(chain);
  lastChainId_ = chain.id;
  chain_ = chain;
  timed_ = std::move(timed);
  status_.state = DriveState::Tracking;
  status_.chainId = chain.id;
  status_.chainFinished = false;
  status_.progress = 0.0;
  status_.remainingSeconds = timed_->duration();
}

TimedTrajectory LowLevelDrive::timedWithMargin(const DriveChain& chain) const {
  try {
    return TimedTrajectory(chain.chain, referenceLimits(config_), chain.startSpeed, 0.0, chain.cruiseOrUnlimited());
  } catch (const InvalidArgumentError&) {
    // A chain planned to the full limits (a stop just long enough) is driven without the margin.
    return TimedTrajectory(chain.chain, config_.limits, chain.startSpeed, 0.0, chain.cruiseOrUnlimited());
  }
}

void LowLevelDrive::stop() { dropChain(DriveState::Braking); }

void LowLevelDrive::dropChain(DriveState next) {
  chain_.reset();
  timed_.reset();
  status_.state = next;
  status_.remainingSeconds = 0.0;
}

VelocityCommand LowLevelDrive::tick(const std::optional<OdometryReading>& latest, double wallSeconds) {
  if (latest && (!lastReading_ || latest->stamp > lastReading_->stamp || latest->id != lastReading_->id)) {
    lastReading_ = latest;
    lastReadingWall_ = wallSeconds;
  }
  const bool fresh = lastReading_ && wallSeconds - lastReadingWall_ <= config_.odometryTimeoutSeconds;
  if (!fresh && (status_.state == DriveState::Tracking || status_.state == DriveState::Settling)) {
    dropChain(DriveState::Braking);
  }
  VelocityCommand wanted;
  switch (status_.state) {
    case DriveState::Idle:
      break;
    case DriveState::Braking:
      wanted = brake();
      if (wanted.translational == 0.0 && wanted.rotational == 0.0) status_.state = DriveState::Idle;
      break;
    case DriveState::Tracking:
      wanted = track(*lastReading_);
      if (status_.state == DriveState::Settling) {
        settleStartWall_ = wallSeconds;
        wanted = settle(*lastReading_, wallSeconds);
      }
      break;
    case DriveState::Settling:
      wanted = settle(*lastReading_, wallSeconds);
      break;
  }
  lastCommand_ = status_.state == DriveState::Braking ? wanted : rateLimited(wanted);
  if (!inFlight_.empty()) {
    inFlight_.pop_front();
    inFlight_.push_back(lastCommand_);
  }
  return lastCommand_;
}

VelocityCommand LowLevelDrive::track(const OdometryReading& reading) {
  const double dt = config_.periodSeconds;
  const double t = reading.stamp - chain_->startTime;
  // The command acts from `acting` on, when the robot will be where the commands in flight take it.
  const double acting = t + dt * static_cast<double>(inFlight_.size());
  if (acting >= timed_->duration()) {
    status_.state = DriveState::Settling;
    return {};
  }
  Pose2D robot = reading.pose;
  for (const VelocityCommand& c : inFlight_) robot = afterCommand(robot, c, dt);
  const ReferenceState now = timed_->stateAt(t);
  const ReferenceState from = inFlight_.empty() ? now : timed_->stateAt(acting);
  const ReferenceState to = timed_->stateAt(acting + dt);
  status_.progress = now.s;
  status_.remainingSeconds = timed_->duration() - std::max(t, 0.0);
  status_.reference = now.pose;
  status_.lateralError = between(now.pose, reading.pose).y;
  // Feed-forward: the reference's mean speeds over the period the command is held.
  const double v = (to.s - from.s) / dt;
  const double w = normalizeAngle(to.pose.theta - from.pose.theta) / dt;
  return controller_.command(robot, from.pose, v, w);
}

VelocityCommand LowLevelDrive::settle(const OdometryReading& reading, double wallSeconds) {
  const Pose2D end = chain_->chain.end();
  const Pose2D e = postureError(reading.pose, end);
  status_.progress = chain_->chain.length();
  status_.remainingSeconds = 0.0;
  status_.reference = end;
  status_.lateralError = between(end, reading.pose).y;
  const bool atEnd = std::hypot(e.x, e.y) <= kSettlePosition && std::abs(e.theta) <= kSettleHeading;
  const bool standing = std::abs(reading.translationalVelocity) <= kSettleSpeed &&
                        std::abs(reading.rotationalVelocity) <= kSettleTurnRate &&
                        std::abs(lastCommand_.translational) <= kSettleSpeed &&
                        std::abs(lastCommand_.rotational) <= kSettleTurnRate;
  if ((atEnd && standing) || wallSeconds - settleStartWall_ > kSettleSeconds) {
    dropChain(DriveState::Idle);
    status_.chainFinished = atEnd && standing;
    return {};
  }
  if (atEnd) return {};
  return {std::clamp(config_.gains.kx * e.x, -kCreepSpeed, kCreepSpeed),
          std::clamp(kCreepTurnGain * e.theta, -kCreepTurnRate, kCreepTurnRate)};
}

VelocityCommand LowLevelDrive::brake() const {
  const double dt = config_.periodSeconds;
  const double stopping = std::max(std::abs(lastCommand_.translational) / config_.limits.maxDeceleration,
                                   std::abs(lastCommand_.rotational) / config_.limits.maxRotationalAcceleration);
  if (stopping <= dt) return {};
  const double keep = 1.0 - dt / stopping;
  return {lastCommand_.translational * keep, lastCommand_.rotational * keep};
}

VelocityCommand LowLevelDrive::rateLimited(const VelocityCommand& wanted) const {
  const MotionLimits& m = config_.limits;
  const double dt = config_.periodSeconds;
  return {towards(lastCommand_.translational, wanted.translational, m.maxAcceleration * dt,
                  m.maxDeceleration * dt),
          towards(lastCommand_.rotational, wanted.rotational, m.maxRotationalAcceleration * dt,
                  m.maxRotationalAcceleration * dt)};
}

DriveStatus LowLevelDrive::status() const { return status_; }

}  // namespace rgnav
