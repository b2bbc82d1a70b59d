// Conversions between Trajectory.idl / LowLevelDrive.idl types and the motion core's (see convert.h).
#include "clientlibs/lowleveldrive/convert.h"

#include "clientlibs/common/convert.h"
#include "core/common/Errors.h"

namespace rgnav {

RGNav::TrajectorySegment toIdl(const TrajectorySegment& s) {
  return {toIdl(s.start), s.length, s.curvature, s.sharpness};
}

TrajectorySegment fromIdl(const RGNav::TrajectorySegment& s) {
  return {fromIdl(s.start), s.length, s.curvature, s.sharpness};
}

RGNav::TrajectorySegmentSeq toIdl(const TrajectoryChain& chain) {
  return toIdlSeq<RGNav::TrajectorySegmentSeq>(chain.segments(), [](const TrajectorySegment& s) { return toIdl(s); });
}

TrajectoryChain fromIdl(const RGNav::TrajectorySegmentSeq& segments) {
  return TrajectoryChain(fromIdlSeq<std::vector<TrajectorySegment>>(
      segments, [](const RGNav::TrajectorySegment& s) { return fromIdl(s); }));
}

RGNav::DriveChain toIdl(const DriveChain& c) {
  return {c.id, toIdl(c.chain), c.startSpeed, toIdlTime(c.startTime), c.cruiseSpeed};
}

DriveChain fromIdl(const RGNav::DriveChain& c) {
  return {c.id, fromIdl(c.segments), c.startSpeed, fromIdl(c.startTime), c.cruiseSpeed};
}

RGNav::MotionLimits toIdl(const MotionLimits& l) {
  return {l.maxVelocity,           l.maxAcceleration,           l.maxDeceleration,
          l.maxRotationalVelocity, l.maxRotationalAcceleration, l.maxLateralAcceleration};
}

MotionLimits fromIdl(const RGNav::MotionLimits& l) {
  return {l.maxVelocity,           l.maxAcceleration,           l.maxDeceleration,
          l.maxRotationalVelocity, l.maxRotationalAcceleration, l.maxLateralAcceleration};
}

RGNav::DriveState toIdl(DriveState state) {
  switch (state) {
    case DriveState::Idle: return RGNav::DRIVE_IDLE;
    case DriveState::Tracking: return RGNav::DRIVE_TRACKING;
    case DriveState::Settling: return RGNav::DRIVE_SETTLING;
    case DriveState::Braking: return RGNav::DRIVE_BRAKING;
  }
  throw InvalidArgumentError("unknown drive state");
}

DriveState fromIdl(RGNav::DriveState state) {
  switch (state) {
    case RGNav::DRIVE_IDLE: return DriveState::Idle;
    case RGNav::DRIVE_TRACKING: return DriveState::Tracking;
    case RGNav::DRIVE_SETTLING: return DriveState::Settling;
    case RGNav::DRIVE_BRAKING: return DriveState::Braking;
    default: break;
  }
  throw InvalidArgumentError("unknown drive state " + std::to_string(static_cast<int>(state)));
}

RGNav::DriveReport toIdl(const DriveReport& r) {
  const DriveStatus& d = r.drive;
  return {toIdl(d.state),       d.chainId,
          d.progress,           d.remainingSeconds,
          toIdl(d.reference),   d.lateralError,
          d.chainFinished,      r.loopPeriodLastSeconds * 1000.0,
          r.loopPeriodP99Seconds * 1000.0, r.commandsSent};
}

DriveReport fromIdl(const RGNav::DriveReport& s) {
  DriveReport r;
  r.drive = {fromIdl(s.state), s.chainId, s.progress, s.remainingSeconds, fromIdl(s.reference), s.lateralError,
             static_cast<bool>(s.chainFinished)};
  r.loopPeriodLastSeconds = s.loopPeriodLastMs / 1000.0;
  r.loopPeriodP99Seconds = s.loopPeriodP99Ms / 1000.0;
  r.commandsSent = s.commandsSent;
  return r;
}

}  // namespace rgnav
