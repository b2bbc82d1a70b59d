// Conversions between Trajectory.idl / LowLevelDrive.idl types and the motion core's
// (core/nav/motion): trajectory segments, drive chains, motion limits, drive states and the
// module's drive report. The only place where the two meet; the Collision Avoidance's client and
// server use the segment, chain and limits conversions too.
#pragma once

#include "LowLevelDrive.hh"
#include "clientlibs/lowleveldrive/DriveReport.h"
#include "core/nav/motion/DriveChain.h"
#include "core/nav/motion/MotionLimits.h"

namespace rgnav {

RGNav::TrajectorySegment toIdl(const TrajectorySegment& segment);
TrajectorySegment fromIdl(const RGNav::TrajectorySegment& segment);
RGNav::TrajectorySegmentSeq toIdl(const TrajectoryChain& chain);
// InvalidArgumentError for segments that are invalid or do not join (TrajectoryChain).
TrajectoryChain fromIdl(const RGNav::TrajectorySegmentSeq& segments);
RGNav::DriveChain toIdl(const DriveChain& chain);
DriveChain fromIdl(const RGNav::DriveChain& chain);  // as the segments' fromIdl
RGNav::MotionLimits toIdl(const MotionLimits& limits);
MotionLimits fromIdl(const RGNav::MotionLimits& limits);
RGNav::DriveState toIdl(DriveState state);
DriveState fromIdl(RGNav::DriveState state);  // InvalidArgumentError for an unknown state
// Loop periods in milliseconds on the wire, seconds in the code.
RGNav::DriveReport toIdl(const DriveReport& report);
DriveReport fromIdl(const RGNav::DriveReport& status);

}  // namespace rgnav
