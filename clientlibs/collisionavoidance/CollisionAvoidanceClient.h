// CollisionAvoidanceClient: drives of the Collision Avoidance module (idl/CollisionAvoidance.idl):
// to a goal the PathPlanning module plans for, or along given targets; cancel; the drive's status.
// driveTo and followTargets are not idempotent: each call carries a random request ID, kept over
// its retries, so that a retry after a lost answer (the module killed meanwhile) gets the drive
// the module started for it instead of a second one. Calls are retried as every client's
// (ClientConnection.h). Errors: BadArgumentError naming the field, ModuleFailedError,
// ModuleUnavailableError.
#pragma once

#include <random>
#include <vector>

#include "CollisionAvoidance.hh"
#include "clientlibs/common/ModuleClient.h"
#include "core/nav/avoidance/DriveProgress.h"

namespace rgnav {

class CollisionAvoidanceClient : public ModuleClientOf<RGNav::CollisionAvoidance> {
 public:
  explicit CollisionAvoidanceClient(ClientSettings settings = ClientSettings::fromEnvironment(),
                                    std::string objectName = "CollisionAvoidance");

  // `request` 0 makes a new request ID (the answer's `request` tells it).
  DriveProgress driveTo(const PlanGoal& goal, std::uint64_t request = 0);
  DriveProgress followTargets(const std::vector<TargetPose>& targets, std::uint64_t request = 0);
  void cancel();
  DriveProgress driveStatus();

 private:
  std::uint64_t requestId(std::uint64_t given);  // `given` if nonzero, else a new one

  std::mt19937_64 requestIds_;
};

}  // namespace rgnav
