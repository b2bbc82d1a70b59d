// PathPlanningClient calls through the retrying connection (see PathPlanningClient.h).
#include "clientlibs/pathplanning/PathPlanningClient.h"

#include <algorithm>

#include "clientlibs/common/convert.h"
#include "clientlibs/pathplanning/convert.h"
#include "core/nav/grid/PlanningErrors.h"

namespace rgnav {

using Planner = RGNav::PathPlanning_ptr;

namespace {

ClientSettings withPlanTimeout(ClientSettings settings) {
  settings.callTimeout = std::max<std::chrono::milliseconds>(settings.callTimeout, PathPlanningClient::kPlanCallTimeout);
  return settings;
}

// A plan the module answered, or its NoPath as NoPathError.
template <class F>
PlanRecord planned(const char* operation, F&& call) {
  try {
    RGNav::PlanInfo_var info = call();
    return fromIdl(info.in());
  } catch (const RGNav::NoPath& e) {
    throw NoPathError(std::string("PathPlanning.") + operation + ": " + e.reason.in());
  }
}

}  // namespace

PathPlanningClient::PathPlanningClient(ClientSettings settings, std::string objectName)
    : ModuleClientOf(std::move(objectName), withPlanTimeout(std::move(settings))), requestIds_([] {
        std::random_device entropy;
        return (std::uint64_t{entropy()} << 32) | entropy();
      }()) {}

std::uint64_t PathPlanningClient::requestId(std::uint64_t given) {
  std::uint64_t id = given;
  while (id == 0) id = requestIds_();
  return id;
}

PlanRecord PathPlanningClient::plan(const Pose2D& start, const PlanGoal& goal, std::uint64_t request) {
  const std::uint64_t id = requestId(request);
  return connection_.call("plan", [&](Planner p) {
    return planned("plan", [&] { return p->plan(id, toIdl(start), toIdl(goal)); });
  });
}

PlanRecord PathPlanningClient::lastPlan() {
  return connection_.call("lastPlan", [](Planner p) {
    RGNav::PlanInfo_var info = p->lastPlan();
    return fromIdl(info.in());
  });
}

PlanRecord PathPlanningClient::planById(PlanId id) {
  return connection_.call("planById", [&](Planner p) {
    RGNav::PlanInfo_var info = p->planById(id);
    return fromIdl(info.in());
  });
}

PlanRecord PathPlanningClient::replanDoorBlocked(GatewayId door, std::uint64_t request) {
  const std::uint64_t id = requestId(request);
  return connection_.call("replanDoorBlocked", [&](Planner p) {
    return planned("replanDoorBlocked", [&] { return p->replanDoorBlocked(id, door.value()); });
  });
}

}  // namespace rgnav
