// Test RG maps for exploration (ExplorationRooms.h).
#include "core/nav/exploration/testing/ExplorationRooms.h"

#include <algorithm>
#include <cmath>

#include "core/lines/ScanPoints.h"

namespace rgnav::testing {
namespace {

constexpr double kFreespaceCellM = 0.15;
constexpr double kSampleM = 0.025;
constexpr double kCrossingOffsetM = 0.5;

}  // namespace

RegionView exploredRegion(RegionId id, const Pose2D& frame, const std::vector<Segment2>& walls,
                          const std::vector<FreeRect>& free) {
  const Pose2D toRegion = inverse(frame);
  RegionView r;
  r.summary.id = id;
  r.summary.frame = frame;
  r.summary.scans = 10;
  for (const Segment2& w : walls) r.lines.push_back({transformPoint(toRegion, w.a), transformPoint(toRegion, w.b)});
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e9), hi = -lo;
  for (const FreeRect& f : free)
    for (const Eigen::Vector2d& c : {f.min, f.max, Eigen::Vector2d(f.min.x(), f.max.y()), Eigen::Vector2d(f.max.x(), f.min.y())}) {
      lo = lo.cwiseMin(transformPoint(toRegion, c));
      hi = hi.cwiseMax(transformPoint(toRegion, c));
    }
  const Eigen::Vector2d origin = (lo / kFreespaceCellM).array().floor().matrix() * kFreespaceCellM;
  const Eigen::Vector2d size = ((hi - origin) / kFreespaceCellM).array().ceil().matrix();
  r.freespace = FreespaceBitmap::allOccupied(kFreespaceCellM, origin, static_cast<int>(size.x()) + 1,
                                             static_cast<int>(size.y()) + 1);
  for (const FreeRect& f : free)
    for (double x = f.min.x() + 0.5 * kSampleM; x < f.max.x(); x += kSampleM)
      for (double y = f.min.y() + 0.5 * kSampleM; y < f.max.y(); y += kSampleM) {
        const Eigen::Vector2d q = (transformPoint(toRegion, {x, y}) - origin) / kFreespaceCellM;
        r.freespace.setFree(static_cast<int>(std::floor(q.x())), static_cast<int>(std::floor(q.y())));
      }
  r.boxMin = lo;
  r.boxMax = hi;
  r.areaM2 = static_cast<double>(r.freespace.freeCount()) * kFreespaceCellM * kFreespaceCellM;
  return r;
}

GatewayView door(GatewayId id, const Eigen::Vector2d& a, const Eigen::Vector2d& b, RegionId sideA, RegionId sideB) {
  GatewayView g;
  g.id = id;
  g.door = true;
  g.gatewayPoints = {a, b};
  const Eigen::Vector2d middle = 0.5 * (a + b), left = Eigen::Vector2d(-(b - a).y(), (b - a).x()).normalized();
  g.crossingPoints = {middle + left * kCrossingOffsetM, middle - left * kCrossingOffsetM};
  g.sideA = sideA;
  g.sideB = sideB;
  g.sideCrossings = {sideA.isNone() ? kNoCrossing : 0, sideB.isNone() ? kNoCrossing : 1};
  return g;
}

PlanningMap planningMap(std::vector<RegionView> regions, std::vector<GatewayView> gateways) {
  std::sort(regions.begin(), regions.end(), [](const RegionView& a, const RegionView& b) { return a.summary.id < b.summary.id; });
  PlanningMap map;
  map.regions = std::move(regions);
  map.gateways = std::move(gateways);
  map.revision = 1;
  return map;
}

}  // namespace rgnav::testing
