// Conversions between PathPlanning.idl types and the route planner's plain types (RoutePlanner.h,
// PlanRecord.h): goals, target poses and whole plans. The only place where the two meet.
#pragma once

#include "PathPlanning.hh"
#include "core/nav/planning/PlanRecord.h"

namespace rgnav {

RGNav::PlanGoal toIdl(const PlanGoal& goal);
PlanGoal fromIdl(const RGNav::PlanGoal& goal);
RGNav::TargetPose toIdl(const TargetPose& target);
TargetPose fromIdl(const RGNav::TargetPose& target);
RGNav::PlanInfo toIdl(const PlanRecord& plan);
PlanRecord fromIdl(const RGNav::PlanInfo& plan);

}  // namespace rgnav
