// CollisionAvoidanceImpl: the CollisionAvoidance.idl servant: check and convert in, service call,
// convert out.
#pragma once

#include "CollisionAvoidance.hh"
#include "servers/collisionavoidance/AvoidanceService.h"
#include "servers/common/ServiceServant.h"

namespace rgnav {

class CollisionAvoidanceImpl : public ServiceServant<POA_RGNav::CollisionAvoidance> {
 public:
  CollisionAvoidanceImpl(ServerRuntime& runtime, AvoidanceService& service);

  RGNav::AvoidanceStatus* driveTo(RGNav::RequestId request, const RGNav::PlanGoal& goal) override;
  RGNav::AvoidanceStatus* followTargets(RGNav::RequestId request, const RGNav::TargetPoseSeq& targets) override;
  void cancel() override;
  RGNav::AvoidanceStatus* driveStatus() override;

 private:
  AvoidanceService& service_;
};

}  // namespace rgnav
