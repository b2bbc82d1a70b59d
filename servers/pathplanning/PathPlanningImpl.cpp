// The PathPlanning.idl servant (see PathPlanningImpl.h).
#include "servers/pathplanning/PathPlanningImpl.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/pathplanning/convert.h"
#include "core/nav/grid/PlanningErrors.h"
#include "servers/common/WireChecks.h"

namespace rgnav {
namespace {

constexpr Raises kPlanning = Raises::InvalidArgument | Raises::NotAvailable;

// Runs planning work; the planner's typed failures become NoPath.
template <class F>
RGNav::PlanInfo* planned(F&& work) {
  try {
    return new RGNav::PlanInfo(toIdl(work()));
  } catch (const NoPathError& e) {
    throw RGNav::NoPath(e.what());
  } catch (const StartBlockedError& e) {
    throw RGNav::NoPath(e.what());
  } catch (const GoalBlockedError& e) {
    throw RGNav::NoPath(e.what());
  }
}

}  // namespace

// The goal as the planner takes it; an argument no goal of its kind can have is refused.
PlanGoal checkedGoal(const RGNav::PlanGoal& goal) {
  switch (goal.kind) {
    case RGNav::GOAL_POINT: wire::requireFinite(goal.point, "goal.point"); break;
    case RGNav::GOAL_REGION: wire::requireId(goal.region, "goal.region"); break;
    case RGNav::GOAL_REGION_NAME:
    case RGNav::GOAL_OBJECT: wire::checkedName(goal.name.in(), "goal.name", false); break;
    default: wire::refuse("goal.kind", "unknown goal kind");
  }
  return fromIdl(goal);
}

PathPlanningImpl::PathPlanningImpl(ServerRuntime& runtime, PathPlanningService& service)
    : ServiceServant(runtime), service_(service) {}

RGNav::PlanInfo* PathPlanningImpl::plan(RGNav::RequestId request, const RGNav::Pose2D& start,
                                        const RGNav::PlanGoal& goal) {
  return serve(kPlanning, [&] {
    wire::requireId(request, "request");
    wire::requireFinite(start, "start");
    const PlanGoal checked = checkedGoal(goal);
    return planned([&] { return service_.plan(request, fromIdl(start), checked); });
  });
}

RGNav::PlanInfo* PathPlanningImpl::lastPlan() {
  return serve(Raises::NotAvailable, [&] { return new RGNav::PlanInfo(toIdl(service_.lastPlan())); });
}

RGNav::PlanInfo* PathPlanningImpl::planById(RGNav::PlanId id) {
  return serve(Raises::InvalidArgument | Raises::NotAvailable, [&] {
    wire::requireId(id, "id");
    return new RGNav::PlanInfo(toIdl(service_.planById(id)));
  });
}

RGNav::PlanInfo* PathPlanningImpl::replanDoorBlocked(RGNav::RequestId request, RGNav::GatewayId door) {
  return serve(kPlanning, [&] {
    wire::requireId(request, "request");
    wire::requireId(door, "door");
    return planned([&] { return service_.replanDoorBlocked(request, GatewayId(door)); });
  });
}

}  // namespace rgnav
