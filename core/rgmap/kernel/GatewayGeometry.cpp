// Placement and sides of the RG Map's gateways; see GatewayGeometry.h.
#include "core/rgmap/kernel/GatewayGeometry.h"

#include <cmath>

#include "core/gateways/passages/SegmentCrossing.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {
namespace {

double cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

// Signed distance of p from the line a-b, positive to its left.
double signedDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return cross(b - a, p - a) / (b - a).norm();
}

}  // namespace

Pose2D odometryToMap(const GatewayRecord& record, const Pose2D& lastScanCorrected) {
  return compose(lastScanCorrected, inverse(record.lastPose));
}

PlacedGateway placeGateway(const Gateway& gateway, const Pose2D& frame) {
  const Pose2D toFrame = compose(inverse(frame), gateway.odomToMap);
  PlacedGateway out;
  for (const Eigen::Vector2d& p : gateway.record.gatewayPoints) out.gatewayPoints.push_back(transformPoint(toFrame, p));
  for (const Eigen::Vector2d& p : gateway.record.crossingPoints)
    out.crossingPoints.push_back(transformPoint(toFrame, p));
  return out;
}

std::size_t nearestCrossing(const PlacedGateway& placed, const Eigen::Vector2d& p) {
  const std::vector<Eigen::Vector2d>& c = placed.crossingPoints;
  std::size_t nearest = 0;
  for (std::size_t i = 1; i < c.size(); ++i)
    if ((c[i] - p).norm() < (c[nearest] - p).norm()) nearest = i;
  return nearest;
}

std::vector<GatewaySegment> sideSegments(const Gateway& gateway, std::size_t side, const Pose2D& frame) {
  const PlacedGateway placed = placeGateway(gateway, frame);
  const std::vector<Eigen::Vector2d>& g = placed.gatewayPoints;
  if (gateway.record.kind == GatewayKind::NarrowPassage) return {{g[0], g[1]}};
  const std::size_t k = gateway.sides[side].crossing;
  if (k == kNoCrossing) return {};
  return {{g[(k + 3) % 4], g[k]}};  // side k of the square runs between corners k - 1 and k
}

Eigen::Vector2d traversalDirection(const Gateway& gateway) {
  const std::size_t a = gateway.sides[kSideA].crossing, b = gateway.sides[kSideB].crossing;
  if (a == kNoCrossing || b == kNoCrossing) return Eigen::Vector2d::Zero();
  const PlacedGateway placed = placeGateway(gateway);
  return (placed.crossingPoints[b] - placed.crossingPoints[a]).normalized();
}

std::optional<std::size_t> robotCrossing(const Gateway& gateway, const Eigen::Vector2d& robot,
                                         const SideEvidenceConfig& config) {
  if (gateway.record.kind != GatewayKind::NarrowPassage) return std::nullopt;
  const PlacedGateway placed = placeGateway(gateway);
  const std::vector<Eigen::Vector2d>& c = placed.crossingPoints;
  const std::vector<Eigen::Vector2d>& g = placed.gatewayPoints;
  if ((c[nearestCrossing(placed, robot)] - robot).norm() > config.rangeM) return std::nullopt;
  const double d = signedDistance(g[0], g[1], robot);
  if (std::abs(d) < config.marginM) return std::nullopt;
  const Eigen::Vector2d along = g[1] - g[0];
  const double t = along.dot(robot - g[0]) / along.norm();
  if (t < -config.besideM || t > along.norm() + config.besideM) return std::nullopt;
  return (d > 0.0) == (signedDistance(g[0], g[1], c[0]) > 0.0) ? 0 : 1;
}

std::optional<std::size_t> lastPathCrossing(const Gateway& gateway, std::span<const Eigen::Vector2d> path,
                                            std::size_t onto) {
  if (gateway.record.kind != GatewayKind::NarrowPassage) return std::nullopt;
  const PlacedGateway placed = placeGateway(gateway);
  const Eigen::Vector2d& a = placed.gatewayPoints[0];
  const Eigen::Vector2d& b = placed.gatewayPoints[1];
  for (std::size_t i = path.size(); i-- > 1;) {
    if (!segmentCrossing(path[i - 1], path[i], a, b)) continue;
    const bool ontoSide =
        (signedDistance(a, b, path[i]) > 0.0) == (signedDistance(a, b, placed.crossingPoints[onto]) > 0.0);
    return ontoSide ? std::optional(i) : std::nullopt;
  }
  return std::nullopt;
}

}  // namespace rgnav
