// Checks of the RG Mapping Kernel's inputs; see KernelInputs.h.
#include "core/rgmap/kernel/KernelInputs.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

void requireFinite(const Pose2D& p, const std::string& what) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.theta))
    throw InvalidArgumentError(what + ": non-finite pose");
}

void validateGatewayEvent(const GatewayEvent& event) {
  const GatewayRecord& r = event.gateway;
  const std::string what = "gateway event " + std::to_string(event.id) + " (gateway " + std::to_string(r.id.value()) + ")";
  if (r.classes.empty()) throw InvalidArgumentError(what + ": no class label");
  const std::size_t points = r.kind == GatewayKind::NarrowPassage ? 2 : 4;
  if (r.gatewayPoints.size() != points || r.crossingPoints.size() != points)
    throw InvalidArgumentError(what + ": want " + std::to_string(points) + " gateway and crossing points");
  const auto bad = [](const Eigen::Vector2d& p) { return !p.allFinite(); };
  if (std::any_of(r.gatewayPoints.begin(), r.gatewayPoints.end(), bad) ||
      std::any_of(r.crossingPoints.begin(), r.crossingPoints.end(), bad))
    throw InvalidArgumentError(what + ": non-finite point");
  if (r.gatewayPoints[0] == r.gatewayPoints[1]) throw InvalidArgumentError(what + ": gateway points coincide");
  requireFinite(r.lastPose, what);
  if (event.kind != GatewayEventKind::Traversed) return;
  const TraversalReport& t = event.traversal;
  if (t.fromSide >= points || t.toSide >= points || t.fromSide == t.toSide)
    throw InvalidArgumentError(what + ": traversal sides out of range or equal");
  if (!t.at.allFinite() || !t.direction.allFinite()) throw InvalidArgumentError(what + ": non-finite traversal");
}

}  // namespace rgnav
