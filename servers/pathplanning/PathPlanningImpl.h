// PathPlanningImpl: the PathPlanning.idl servant: check and convert in, service call, convert
// out; the planner's typed failures (NoPathError, and a start or goal the region planner finds
// blocked) become the typed NoPath exception with the reason.
#pragma once

#include "PathPlanning.hh"
#include "servers/common/ServiceServant.h"
#include "servers/pathplanning/PathPlanningService.h"

namespace rgnav {

// The goal as the planner takes it; InvalidArgument naming the field for an argument no goal of
// its kind can have (also the Collision Avoidance's driveTo).
PlanGoal checkedGoal(const RGNav::PlanGoal& goal);

class PathPlanningImpl : public ServiceServant<POA_RGNav::PathPlanning> {
 public:
  PathPlanningImpl(ServerRuntime& runtime, PathPlanningService& service);

  RGNav::PlanInfo* plan(RGNav::RequestId request, const RGNav::Pose2D& start, const RGNav::PlanGoal& goal) override;
  RGNav::PlanInfo* lastPlan() override;
  RGNav::PlanInfo* planById(RGNav::PlanId id) override;
  RGNav::PlanInfo* replanDoorBlocked(RGNav::RequestId request, RGNav::GatewayId door) override;

 private:
  PathPlanningService& service_;
};

}  // namespace rgnav
