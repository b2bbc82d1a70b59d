// Conversions between CollisionAvoidance.idl types and DriveProgress (see convert.h).
#include "clientlibs/collisionavoidance/convert.h"

#include "clientlibs/pathplanning/convert.h"
#include "core/common/Errors.h"

namespace rgnav {

RGNav::AvoidanceState toIdl(DrivePhase phase) {
  switch (phase) {
    case DrivePhase::Idle: return RGNav::AVOIDANCE_IDLE;
    case DrivePhase::Planning: return RGNav::AVOIDANCE_PLANNING;
    case DrivePhase::Driving: return RGNav::AVOIDANCE_DRIVING;
    case DrivePhase::Waiting: return RGNav::AVOIDANCE_WAITING;
    case DrivePhase::Blocked: return RGNav::AVOIDANCE_BLOCKED;
    case DrivePhase::Replanning: return RGNav::AVOIDANCE_REPLANNING;
    case DrivePhase::Reached: return RGNav::AVOIDANCE_REACHED;
    case DrivePhase::Failed: return RGNav::AVOIDANCE_FAILED;
  }
  throw InvalidArgumentError("unknown drive phase");
}

DrivePhase fromIdl(RGNav::AvoidanceState state) {
  switch (state) {
    case RGNav::AVOIDANCE_IDLE: return DrivePhase::Idle;
    case RGNav::AVOIDANCE_PLANNING: return DrivePhase::Planning;
    case RGNav::AVOIDANCE_DRIVING: return DrivePhase::Driving;
    case RGNav::AVOIDANCE_WAITING: return DrivePhase::Waiting;
    case RGNav::AVOIDANCE_BLOCKED: return DrivePhase::Blocked;
    case RGNav::AVOIDANCE_REPLANNING: return DrivePhase::Replanning;
    case RGNav::AVOIDANCE_REACHED: return DrivePhase::Reached;
    case RGNav::AVOIDANCE_FAILED: return DrivePhase::Failed;
    default: break;
  }
  throw InvalidArgumentError("unknown drive state " + std::to_string(static_cast<int>(state)));
}

RGNav::AvoidanceStatus toIdl(const DriveProgress& p) {
  RGNav::AvoidanceStatus out;
  out.request = p.request;
  out.state = toIdl(p.phase);
  out.hasGoal = p.hasGoal;
  out.goal = toIdl(p.goal);
  out.plan = p.plan;
  out.targetIndex = p.targetIndex;
  out.targetCount = p.targetCount;
  out.distanceLeftM = p.distanceLeftM;
  out.chainsSent = p.chainsSent;
  out.replans = p.replans;
  out.reason = p.reason.c_str();
  return out;
}

DriveProgress fromIdl(const RGNav::AvoidanceStatus& info) {
  DriveProgress p;
  p.request = info.request;
  p.phase = fromIdl(info.state);
  p.hasGoal = info.hasGoal;
  p.goal = fromIdl(info.goal);
  p.plan = info.plan;
  p.targetIndex = info.targetIndex;
  p.targetCount = info.targetCount;
  p.distanceLeftM = info.distanceLeftM;
  p.chainsSent = info.chainsSent;
  p.replans = info.replans;
  p.reason = info.reason.in();
  return p;
}

}  // namespace rgnav
