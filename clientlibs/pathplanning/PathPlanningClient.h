// PathPlanningClient: plans of the PathPlanning module (idl/PathPlanning.idl): plan from a start
// to a goal, the last plan, a plan by ID, and a plan made again after a door was found blocked.
// plan and replanDoorBlocked are not idempotent: each call carries a random request ID, kept over
// its retries, so that a retry after a lost answer (the module killed meanwhile, say) gets the
// plan the module made for it, or the same plan made again by the restarted module. Calls are
// retried as every client's (ClientConnection.h); planning waits up to kPlanCallTimeout for its
// answer (the first plan on a large map builds the region grids). Errors: NoPathError with the
// module's reason, BadArgumentError naming the field, NotAvailableError (no map yet, no such
// plan), ModuleFailedError, ModuleUnavailableError.
#pragma once

#include <chrono>
#include <random>

#include "PathPlanning.hh"
#include "clientlibs/common/ModuleClient.h"
#include "core/nav/planning/PlanRecord.h"

namespace rgnav {

class PathPlanningClient : public ModuleClientOf<RGNav::PathPlanning> {
 public:
  static constexpr std::chrono::seconds kPlanCallTimeout{30};

  explicit PathPlanningClient(ClientSettings settings = ClientSettings::fromEnvironment(),
                              std::string objectName = "PathPlanning");

  // `request` 0 makes a new request ID; a caller that asks again for a request whose answer it
  // lost passes that request's ID (PlanRecord::request).
  PlanRecord plan(const Pose2D& start, const PlanGoal& goal, std::uint64_t request = 0);
  PlanRecord lastPlan();
  PlanRecord planById(PlanId id);
  PlanRecord replanDoorBlocked(GatewayId door, std::uint64_t request = 0);

 private:
  std::uint64_t requestId(std::uint64_t given);  // `given` if nonzero, else a new one

  std::mt19937_64 requestIds_;
};

}  // namespace rgnav
