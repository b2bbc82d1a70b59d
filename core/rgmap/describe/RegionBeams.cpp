// Beams of a scan clipped to the region; see RegionBeams.h.
#include "core/rgmap/describe/RegionBeams.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/gateways/passages/SegmentCrossing.h"

namespace rgnav {

RegionBeams regionBeams(const LaserScan& scan, const Pose2D& sensorPose, std::span<const GatewaySegment> gateways,
                        double noReturnFreeRangeM) {
  if (!std::isfinite(sensorPose.x) || !std::isfinite(sensorPose.y) || !std::isfinite(sensorPose.theta))
    throw InvalidArgumentError("region beams: sensor pose must be finite");
  if (!std::isfinite(scan.startAngle) || !std::isfinite(scan.angleIncrement))
    throw InvalidArgumentError("region beams: scan angles must be finite");
  if (!std::isfinite(noReturnFreeRangeM) || noReturnFreeRangeM < 0.0)
    throw InvalidArgumentError("region beams: noReturnFreeRangeM must be finite and >= 0");
  for (const GatewaySegment& g : gateways)
    if (!g.a.allFinite() || !g.b.allFinite()) throw InvalidArgumentError("region beams: gateway ends must be finite");

  const bool hasMaxRange = scan.maxRange > 0.0;
  const double noReturnLength = hasMaxRange ? std::min(noReturnFreeRangeM, scan.maxRange) : noReturnFreeRangeM;
  RegionBeams out;
  out.origin = {sensorPose.x, sensorPose.y};
  out.beams.reserve(scan.ranges.size());
  // The beam direction is turned by the increment from beam to beam instead of calling cos and
  // sin per beam (the rounding drift over a few thousand beams stays far below a millimetre).
  const double first = sensorPose.theta + scan.startAngle;
  const double stepCos = std::cos(scan.angleIncrement), stepSin = std::sin(scan.angleIncrement);
  Eigen::Vector2d direction(std::cos(first), std::sin(first));
  for (const float range : scan.ranges) {
    if (range > 0.0f) {  // false for NaN
      const bool measured = std::isfinite(range) && !(hasMaxRange && range >= scan.maxRange);
      RegionBeam beam{out.origin + (measured ? double(range) : noReturnLength) * direction, measured};
      for (const GatewaySegment& g : gateways) {
        if (const auto crossing = segmentCrossing(out.origin, beam.end, g.a, g.b)) beam = {*crossing, false};
      }
      out.beams.push_back(beam);
    }
    direction = Eigen::Vector2d(stepCos * direction.x() - stepSin * direction.y(),
                                stepSin * direction.x() + stepCos * direction.y());
  }
  return out;
}

}  // namespace rgnav
