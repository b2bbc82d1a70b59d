// Gateway point helpers; see GatewayPoints.h.
#include "core/gateways/vlm/GatewayPoints.h"

#include <algorithm>

#include "core/lines/ScanPoints.h"

namespace rgnav {

GatewayPoints squareGatewayArea(double width) {
  const double h = width / 2.0;
  return {Eigen::Vector2d(-h, h), Eigen::Vector2d(h, h), Eigen::Vector2d(h, -h), Eigen::Vector2d(-h, -h)};
}

Eigen::Vector2d gatewayCentre(const GatewayPoints& points) {
  return 0.25 * (points[0] + points[1] + points[2] + points[3]);
}

GatewayPoints transformed(const GatewayPoints& points, const Pose2D& pose) {
  GatewayPoints out;
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = transformPoint(pose, points[i]);
  return out;
}

double largestPointDistance(const GatewayPoints& a, const GatewayPoints& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
  return d;
}

double depthPastEntrance(const GatewayPoints& points, const Eigen::Vector2d& p) {
  const Eigen::Vector2d entrance = points[kHiddenLeft] - points[kHiddenRight];
  const double length = entrance.norm();
  if (length <= 0.0) return 0.0;
  // Unit normal of the entrance pointing to the front side of the quadrangle.
  Eigen::Vector2d inward(-entrance.y() / length, entrance.x() / length);
  const Eigen::Vector2d front = 0.5 * (points[kFrontLeft] + points[kFrontRight]);
  if (inward.dot(front - points[kHiddenRight]) < 0.0) inward = -inward;
  return inward.dot(p - points[kHiddenRight]);
}

}  // namespace rgnav
