// On-line and over-line freespace measures per sector; see FreespaceMeasures.h.
#include "core/gateways/vlm/FreespaceMeasures.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

const Eigen::Vector2d kRobot = Eigen::Vector2d::Zero();

double bearing(const Eigen::Vector2d& p) { return std::atan2(p.y(), p.x()); }

struct SectorGeometry {
  double from, to;  // bearings, from < to; beams in [from, to)
  PlanarLine line;
  PlanarLine setBack;
};

SectorGeometry sector(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const PlanarLine& line, double setback) {
  // Away from the robot: against the side of the line the robot is on.
  const double away = line.signedOffset(kRobot) > 0.0 ? -1.0 : 1.0;
  const double ba = bearing(a), bb = bearing(b);
  return {std::min(ba, bb), std::max(ba, bb), line, line.shifted(away * setback)};
}

}  // namespace

SectorFreespace freespaceMeasures(const VlmHypothesis& vlm, const LaserScan& scan, const FreespaceParams& params) {
  if (!(params.onLineLowerM <= params.onLineUpperM) || !(params.frontSetbackM >= 0.0) || !(params.sideSetbackM >= 0.0))
    throw InvalidArgumentError("freespace measures: need lower <= upper threshold and non-negative setbacks");
  const GatewayPoints& g = vlm.gatewayPoints;
  const std::array<SectorGeometry, kSectorCount> sectors{
      sector(g[kFrontLeft], g[kHiddenLeft], vlm.left, params.sideSetbackM),
      sector(g[kFrontRight], g[kFrontLeft], vlm.front, params.frontSetbackM),
      sector(g[kHiddenRight], g[kFrontRight], vlm.right, params.sideSetbackM)};
  std::array<std::size_t, kSectorCount> onCount{}, overCount{};
  SectorFreespace result;
  for (std::size_t beam = 0; beam < scan.ranges.size(); ++beam) {
    const double d = scan.ranges[beam];
    if (std::isnan(d)) continue;
    const double b = scan.startAngle + double(beam) * scan.angleIncrement;
    for (std::size_t s = 0; s < kSectorCount; ++s) {
      if (b < sectors[s].from || b >= sectors[s].to) continue;
      const Eigen::Vector2d ray(std::cos(b), std::sin(b));
      ++result.beams[s];
      const auto t = rayDistance(kRobot, ray, sectors[s].line);
      if (t && d - *t < params.onLineLowerM) continue;  // occluded
      ++result.seenBeams[s];
      if (t && d - *t <= params.onLineUpperM) ++onCount[s];
      if (const auto tPar = rayDistance(kRobot, ray, sectors[s].setBack); tPar && d > *tPar) ++overCount[s];
    }
  }
  for (std::size_t s = 0; s < kSectorCount; ++s) {
    if (result.seenBeams[s] == 0) continue;
    result.onLine[s] = double(onCount[s]) / double(result.seenBeams[s]);
    result.overLine[s] = double(overCount[s]) / double(result.seenBeams[s]);
  }
  return result;
}

}  // namespace rgnav
