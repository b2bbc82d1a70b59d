// PathPlanningService: the PathPlanning module's work behind its servant (thesis 2.1.3, 5.4): plans
// with the route planner (RoutePlanner.h) on the RG Mapping Kernel's map (KernelMapCache.h),
// numbers and keeps the plans (PlanStore.h) and reports doors found blocked to the kernel.
// Exactly once: a request ID the module has answered gets the plan it made for it, also after a
// restart, because the plans with their request IDs are checkpointed (written atomically to
// `checkpointFile` before the answer leaves) and reloaded at start. A request whose answer was
// lost with a killed module is planned again by the restarted one: under the same ID (the
// numbering resumes from the checkpoint) and with the same targets (a plan depends only on its
// arguments and the map revision). A checkpoint that cannot be written degrades the module and is
// tried again at the next plan after a backoff (CheckpointRetry.h); the plans are still served,
// but a restart meanwhile forgets those made since the last checkpoint written, and gives their
// IDs again.
// One plan at a time: the planner and the cache are guarded by one lock.
#pragma once

#include <mutex>
#include <string>

#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "core/nav/planning/RoutePlanner.h"
#include "servers/common/CheckpointRetry.h"
#include "servers/common/ModuleHealth.h"
#include "clientlibs/pathplanning/KernelMapCache.h"
#include "servers/pathplanning/PlanStore.h"

namespace rgnav {

struct PathPlanningServiceOptions {
  std::string checkpointFile;  // empty: no checkpoints
  std::size_t keptPlans = PlanStore::kKeptPlans;
};

class PathPlanningService {
 public:
  // Loads the checkpoint if there is one (FormatError if it is damaged: the module then fails at
  // start and the operator decides). Does not contact the kernel yet.
  PathPlanningService(const RoutePlannerConfig& config, const ClientSettings& settings, const std::string& kernelObject,
                      PathPlanningServiceOptions options, ModuleHealth& health);

  // Throws NoPathError (PlanningErrors.h) with the reason, InvalidArgumentError for a non-finite
  // start or goal, NotAvailableError while the kernel has no map or does not answer.
  PlanRecord plan(std::uint64_t request, const Pose2D& start, const PlanGoal& goal);
  // NotAvailableError before the first plan / for a plan no longer kept.
  PlanRecord lastPlan();
  PlanRecord planById(PlanId id);
  // Reports the door blocked to the kernel (InvalidArgumentError for a gateway that is no door of
  // its graph) and plans the last plan's start and goal again; as plan() otherwise.
  PlanRecord replanDoorBlocked(std::uint64_t request, GatewayId door);
  // The ID the next plan gets.
  PlanId nextPlanId();

 private:
  // Under lock: the planner on the kernel's current map; NotAvailableError without one.
  void refreshMap();
  PlanRecord planAndKeep(std::uint64_t request, const Pose2D& start, const PlanGoal& goal);  // under lock
  void checkpoint();  // under lock

  PathPlanningServiceOptions options_;
  ModuleHealth& health_;
  RgMappingKernelClient kernel_;
  std::mutex mutex_;
  KernelMapCache cache_;
  RoutePlanner planner_;
  PlanStore plans_;
  CheckpointRetry retry_;
};

}  // namespace rgnav
