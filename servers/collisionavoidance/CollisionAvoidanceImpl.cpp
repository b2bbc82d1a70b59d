// The CollisionAvoidance.idl servant (see CollisionAvoidanceImpl.h).
#include "servers/collisionavoidance/CollisionAvoidanceImpl.h"

#include "clientlibs/collisionavoidance/convert.h"
#include "clientlibs/pathplanning/convert.h"
#include "servers/common/WireChecks.h"
#include "servers/pathplanning/PathPlanningImpl.h"

namespace rgnav {

CollisionAvoidanceImpl::CollisionAvoidanceImpl(ServerRuntime& runtime, AvoidanceService& service)
    : ServiceServant(runtime), service_(service) {}

RGNav::AvoidanceStatus* CollisionAvoidanceImpl::driveTo(RGNav::RequestId request, const RGNav::PlanGoal& goal) {
  return serve(Raises::InvalidArgument, [&] {
    wire::requireId(request, "request");
    return new RGNav::AvoidanceStatus(toIdl(service_.driveTo(request, checkedGoal(goal))));
  });
}

RGNav::AvoidanceStatus* CollisionAvoidanceImpl::followTargets(RGNav::RequestId request,
                                                              const RGNav::TargetPoseSeq& targets) {
  return serve(Raises::InvalidArgument, [&] {
    wire::requireId(request, "request");
    if (targets.length() == 0) wire::refuse("targets", "no targets");
    std::vector<TargetPose> converted;
    for (CORBA::ULong i = 0; i < targets.length(); ++i) {
      wire::requireFinite(targets[i].pose, "targets");
      converted.push_back(fromIdl(targets[i]));
    }
    return new RGNav::AvoidanceStatus(toIdl(service_.followTargets(request, std::move(converted))));
  });
}

void CollisionAvoidanceImpl::cancel() {
  serve(Raises::FailedOnly, [&] { service_.cancel(); });
}

RGNav::AvoidanceStatus* CollisionAvoidanceImpl::driveStatus() {
  return serve(Raises::FailedOnly, [&] { return new RGNav::AvoidanceStatus(toIdl(service_.status())); });
}

}  // namespace rgnav
