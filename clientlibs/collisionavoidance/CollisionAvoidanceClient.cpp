// CollisionAvoidanceClient calls through the retrying connection (see CollisionAvoidanceClient.h).
#include "clientlibs/collisionavoidance/CollisionAvoidanceClient.h"

#include "clientlibs/collisionavoidance/convert.h"
#include "clientlibs/pathplanning/convert.h"

namespace rgnav {

using Avoidance = RGNav::CollisionAvoidance_ptr;

CollisionAvoidanceClient::CollisionAvoidanceClient(ClientSettings settings, std::string objectName)
    : ModuleClientOf(std::move(objectName), std::move(settings)), requestIds_([] {
        std::random_device entropy;
        return (std::uint64_t{entropy()} << 32) | entropy();
      }()) {}

std::uint64_t CollisionAvoidanceClient::requestId(std::uint64_t given) {
  std::uint64_t id = given;
  while (id == 0) id = requestIds_();
  return id;
}

DriveProgress CollisionAvoidanceClient::driveTo(const PlanGoal& goal, std::uint64_t request) {
  const std::uint64_t id = requestId(request);
  return connection_.call("driveTo", [&](Avoidance a) {
    RGNav::AvoidanceStatus_var info = a->driveTo(id, toIdl(goal));
    return fromIdl(info.in());
  });
}

DriveProgress CollisionAvoidanceClient::followTargets(const std::vector<TargetPose>& targets, std::uint64_t request) {
  const std::uint64_t id = requestId(request);
  const auto seq =
      toIdlSeq<RGNav::TargetPoseSeq>(targets, [](const TargetPose& t) { return toIdl(t); });
  return connection_.call("followTargets", [&](Avoidance a) {
    RGNav::AvoidanceStatus_var info = a->followTargets(id, seq);
    return fromIdl(info.in());
  });
}

void CollisionAvoidanceClient::cancel() {
  connection_.call("cancel", [](Avoidance a) { a->cancel(); });
}

DriveProgress CollisionAvoidanceClient::driveStatus() {
  return connection_.call("driveStatus", [](Avoidance a) {
    RGNav::AvoidanceStatus_var info = a->driveStatus();
    return fromIdl(info.in());
  });
}

}  // namespace rgnav
