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

}  // namespace

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
}

void LowLevelDrive::setChain(const DriveChain& chain) {
  if (chain.id <= lastChainId_) {
    throw InvalidArgumentError("low-level drive: chain id " + std::to_string(chain.id) +
                               " is not above the last one (" + std::to_string(lastChainId_) + ")");
  }
  TimedTrajectory timed(chain.chain, config_.limits, chain.startSpeed, 0.0);
  lastChainId_ = chain.id;
  chain_ = chain;
  timed_ = std::move(timed);
  status_.state = DriveState::Tracking;
  status_.chainId = chain.id;
  status_.chainFinished = false;
  status_.progress = 0.0;
  status_.remainingSeconds = timed_->duration();
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
  return lastCommand_;
}

VelocityCommand LowLevelDrive::track(const OdometryReading& reading) {
  const double t = reading.stamp - chain_->startTime;
  if (t >= timed_->duration()) {
    status_.state = DriveState::Settling;
    return {};
  }
  const ReferenceState now = timed_->stateAt(t);
  const ReferenceState next = timed_->stateAt(t + config_.periodSeconds);
  const double dt = config_.periodSeconds;
  const double v = (next.s - now.s) / dt;
  const double w = normalizeAngle(next.pose.theta - now.pose.theta) / dt;
  status_.progress = now.s;
  status_.remainingSeconds = timed_->duration() - std::max(t, 0.0);
  status_.reference = now.pose;
  status_.lateralError = between(now.pose, reading.pose).y;
  return controller_.command(reading.pose, now.pose, v, w);
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
    status_.chainFinished = true;
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
