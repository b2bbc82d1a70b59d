// The PathPlanning module's planning, plan store and checkpoints (see PathPlanningService.h).
#include "servers/pathplanning/PathPlanningService.h"

#include <optional>

#include "core/common/AtomicFile.h"
#include "core/nav/grid/PlanningErrors.h"

namespace rgnav {
namespace {

PlanStore loadCheckpoint(const std::string& file, std::size_t kept) {
  const std::optional<std::string> saved = readCheckpoint(file);
  return saved ? PlanStore::deserialize(*saved, file, kept) : PlanStore(kept);
}

}  // namespace

PathPlanningService::PathPlanningService(const RoutePlannerConfig& config, const ClientSettings& settings,
                                         const std::string& kernelObject, PathPlanningServiceOptions options,
                                         ModuleHealth& health)
    : options_(std::move(options)),
      health_(health),
      kernel_(settings, kernelObject),
      cache_(kernel_),
      planner_(config),
      plans_(loadCheckpoint(options_.checkpointFile, options_.keptPlans)),
      retry_(health) {
  health_.set("resumed_after_plan", plans_.nextId() - 1);
}

void PathPlanningService::refreshMap() {
  try {
    if (cache_.refresh()) {
      planner_.setMap(cache_.map());
      health_.set("map_revision", cache_.revision());
      health_.set("regions_fetched", cache_.regionsFetched());
    }
  } catch (const ModuleUnavailableError& e) {
    throw NotAvailableError(std::string("the RG Mapping Kernel does not answer: ") + e.what());
  }
  if (cache_.empty()) throw NotAvailableError("the RG Mapping Kernel has no map yet");
}

PlanRecord PathPlanningService::planAndKeep(std::uint64_t request, const Pose2D& start, const PlanGoal& goal) {
  refreshMap();
  PlanRecord record{plans_.nextId(), request, start, goal, {}};
  try {
    record.plan = planner_.plan(start, goal);
  } catch (const NoPathError&) {
    health_.add("no_path");
    throw;
  }
  plans_.add(record);
  health_.add("plans");
  checkpoint();
  return record;
}

void PathPlanningService::checkpoint() {
  if (options_.checkpointFile.empty() || !retry_.due()) return;
  try {
    writeFileAtomically(options_.checkpointFile, plans_.serialize());
    retry_.succeeded();
  } catch (const FileError& e) {
    retry_.failed(e.what());
  }
}

PlanRecord PathPlanningService::plan(std::uint64_t request, const Pose2D& start, const PlanGoal& goal) {
  std::lock_guard lock(mutex_);
  if (const PlanRecord* answered = plans_.byRequest(request)) return *answered;
  return planAndKeep(request, start, goal);
}

PlanId PathPlanningService::nextPlanId() {
  std::lock_guard lock(mutex_);
  return plans_.nextId();
}

PlanRecord PathPlanningService::lastPlan() {
  std::lock_guard lock(mutex_);
  const PlanRecord* last = plans_.last();
  if (!last) throw NotAvailableError("no plan made yet");
  return *last;
}

PlanRecord PathPlanningService::planById(PlanId id) {
  std::lock_guard lock(mutex_);
  const PlanRecord* found = plans_.byId(id);
  if (!found) throw NotAvailableError("plan " + std::to_string(id) + " is not kept (the next plan is " +
                                      std::to_string(plans_.nextId()) + ")");
  return *found;
}

PlanRecord PathPlanningService::replanDoorBlocked(std::uint64_t request, GatewayId door) {
  std::lock_guard lock(mutex_);
  if (const PlanRecord* answered = plans_.byRequest(request)) return *answered;
  const PlanRecord* last = plans_.last();
  if (!last) throw NotAvailableError("no plan made yet to plan again");
  const PlanRecord previous = *last;
  try {
    kernel_.reportDoorState(door, false, request);
  } catch (const ModuleUnavailableError& e) {
    throw NotAvailableError(std::string("the RG Mapping Kernel does not answer: ") + e.what());
  }
  health_.add("doors_reported_blocked");
  return planAndKeep(request, previous.start, previous.goal);
}

}  // namespace rgnav
