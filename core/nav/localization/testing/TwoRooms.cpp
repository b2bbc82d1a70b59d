// The two-room test map and its ray caster (TwoRooms.h).
#include "core/nav/localization/testing/TwoRooms.h"

#include <cmath>
#include <limits>

#include "core/lines/ScanPoints.h"

namespace rgnav::testing {
namespace {

const Pose2D kFrame2{8.0, 0.5, 0.4};

// A map point in `frame`.
Eigen::Vector2d toFrame(const Pose2D& frame, const Eigen::Vector2d& p) { return transformPoint(inverse(frame), p); }

RegionView room(RegionId id, const Pose2D& frame, const std::vector<Segment2>& walls, double x0) {
  RegionView r;
  r.summary.id = id;
  r.summary.frame = frame;
  r.summary.scans = 10;
  r.summary.gateways = {GatewayId{1}};
  for (const Segment2& w : walls) r.lines.push_back({toFrame(frame, w.a), toFrame(frame, w.b)});
  // Freespace: the room's interior, sampled in the map frame and set in the region frame.
  r.freespace = FreespaceBitmap::allOccupied(0.15, Eigen::Vector2d(-12.0, -12.0), 160, 160);
  for (double x = x0 + 0.05; x < x0 + 4.0; x += 0.05)
    for (double y = 0.05; y < 4.0; y += 0.05) {
      const Eigen::Vector2d q = toFrame(frame, {x, y}) - r.freespace.originM;
      r.freespace.setFree(static_cast<int>(q.x() / 0.15), static_cast<int>(q.y() / 0.15));
    }
  return r;
}

}  // namespace

TwoRooms twoRooms() {
  TwoRooms m;
  const std::vector<Segment2> left{{{0, 0}, {4, 0}}, {{0, 4}, {4, 4}}, {{0, 0}, {0, 4}}, {{4, 0}, {4, 1.6}}, {{4, 2.4}, {4, 4}},
                                   {{1.0, 3.0}, {1.5, 3.0}}};
  const std::vector<Segment2> right{{{4, 0}, {8, 0}}, {{4, 4}, {8, 4}}, {{8, 0}, {8, 4}}, {{4, 0}, {4, 1.6}}, {{4, 2.4}, {4, 4}},
                                    {{6.0, 0.8}, {6.0, 1.6}}};
  m.walls = left;
  m.walls.insert(m.walls.end(), right.begin(), right.end());
  m.regions = {room(RegionId{1}, Pose2D{}, left, 0.0), room(RegionId{2}, kFrame2, right, 4.0)};
  GatewayView door;
  door.id = GatewayId{1};
  door.door = true;
  door.gatewayPoints = {{4.0, 1.6}, {4.0, 2.4}};
  door.crossingPoints = {{3.6, 2.0}, {4.4, 2.0}};
  door.sideA = RegionId{1};
  door.sideB = RegionId{2};
  door.sideCrossings = {0, 1};
  m.gateways = {door};
  return m;
}

LaserScan simulatedScan(const std::vector<Segment2>& walls, const Pose2D& truth, const Pose2D& odometry, DataId id) {
  LaserScan scan;
  scan.id = id;
  scan.odometry = odometry;
  scan.startAngle = -M_PI / 2.0;
  scan.angleIncrement = M_PI / 180.0;
  scan.maxRange = 10.0;
  for (int i = 0; i < 181; ++i) {
    const double a = truth.theta + scan.startAngle + i * scan.angleIncrement;
    const Eigen::Vector2d o(truth.x, truth.y), d(std::cos(a), std::sin(a));
    double best = std::numeric_limits<double>::infinity();
    for (const Segment2& w : walls) {
      const Eigen::Vector2d e = w.b - w.a;
      const double den = d.x() * e.y() - d.y() * e.x();
      if (std::abs(den) < 1e-12) continue;
      const Eigen::Vector2d q = w.a - o;
      const double t = (q.x() * e.y() - q.y() * e.x()) / den, u = (q.x() * d.y() - q.y() * d.x()) / den;
      if (t > 0.0 && u >= 0.0 && u <= 1.0) best = std::min(best, t);
    }
    scan.ranges.push_back(best < scan.maxRange ? static_cast<float>(best) : LaserScan::kNoReturn);
  }
  return scan;
}

}  // namespace rgnav::testing
