// GatewayGeometry: where a gateway of the RG Map lies and which side of it the robot is on (thesis
// 2.1.2: gateway points, crossing points, traversal directions; 6.1.1: the side a gateway is
// observed from tells which region the robot is in).
//   - Placement: the detector reports a gateway in its odometry frame with the scan it was last
//     seen in; the kernel places it with that scan's correction,
//     p_map = corrected(lastScan) ∘ odometry(lastScan)^-1 ∘ p_odom, and derives any region's view
//     of it from the map frame.
//   - Gateway lines of a region: a narrow passage's line between its gateway points; for a
//     hallway area, the side of its square the region lies beyond (corners hidden-left,
//     front-left, front-right, hidden-right; sides hidden, left, front, right), so what lies in the
//     square or beyond another side is kept out of the region's description.
//   - The robot's side of a narrow passage: the crossing point nearest to the robot, if it is
//     within rangeM; not decided while the robot is within marginM of the passage's line (it may
//     be crossing it right now), nor (ours) while it is more than besideM beside the passage's
//     ends: a robot in the next room along a hallway wall is on the same side of a door's line as
//     the room behind that door, but not in it. Not decided for hallway areas, whose sides come
//     from the traversals the detector reports (RgMappingKernel.h).
//   - A missed traversal (6.1.1, figure 6.4): the last step of the robot's path that crossed a
//     narrow passage's line onto the side the robot is on now. Deliberate difference: not
//     searched for hallway areas, whose traversals the detector reports itself
//     (HallwayAreaTracker.h).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/gateways/detection/GatewayRecord.h"
#include "core/rgmap/describe/GatewaySegment.h"
#include "core/rgmap/kernel/RgMapState.h"

namespace rgnav {

struct SideEvidenceConfig {
  double marginM = 0.3;  // no side within this distance of the gateway line (area)
  // No side farther than this from the nearest crossing point: from farther away the robot often
  // sees a gateway from another region than the one beyond it (docs/EVALUATION.md compares
  // ranges). A loop is then closed by observation only near the gateway, and otherwise
  // when the robot passes it.
  double rangeM = 0.7;
  double besideM = 0.5;  // a passage: no side farther than this beside its line's ends
};

template <class V>
void describe(V& v, SideEvidenceConfig& c) {
  v.field("margin_m", c.marginM);
  v.field("range_m", c.rangeM);
  v.field("beside_m", c.besideM);
}

// corrected(lastScan) ∘ odometry(lastScan)^-1, with record.lastPose as odometry(lastScan).
Pose2D odometryToMap(const GatewayRecord& record, const Pose2D& lastScanCorrected);

struct PlacedGateway {
  std::vector<Eigen::Vector2d> gatewayPoints;
  std::vector<Eigen::Vector2d> crossingPoints;
};

// The gateway's points in `frame` (a pose in the map frame; the identity gives the map frame).
PlacedGateway placeGateway(const Gateway& gateway, const Pose2D& frame = {});

// The index of the crossing point of `placed` nearest to `p`.
std::size_t nearestCrossing(const PlacedGateway& placed, const Eigen::Vector2d& p);

// The gateway lines that bound the region on side `side` of `gateway`, in `frame`; none for a
// hallway area's side whose crossing point is not known yet.
std::vector<GatewaySegment> sideSegments(const Gateway& gateway, std::size_t side, const Pose2D& frame);

// The traversal direction from side A to side B (unit vector, map frame); zero while side B's
// crossing point is not known.
Eigen::Vector2d traversalDirection(const Gateway& gateway);

// The index of the crossing point on the robot's side of a narrow passage, or nullopt when
// undecided or the gateway is a hallway area (see above).
std::optional<std::size_t> robotCrossing(const Gateway& gateway, const Eigen::Vector2d& robotInMap,
                                         const SideEvidenceConfig& config);

// The index i >= 1 of the last step path[i - 1] -> path[i] (map frame) that crosses a narrow
// passage's line, if it ends on the side of crossing point `onto`; nullopt if no step crosses,
// the last crossing ends on the other side, or the gateway is a hallway area.
std::optional<std::size_t> lastPathCrossing(const Gateway& gateway, std::span<const Eigen::Vector2d> path,
                                            std::size_t onto);

}  // namespace rgnav
