// Sides of a door a region's robot stood on and saw it from; see DoorSides.h.
#include "core/rgmap/kernel/DoorSides.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

// Calls visit(side, scan) for every scan of `region` in front of `door` until it returns the
// sides wanted; returns the sides visit gave.
template <typename Visit>
unsigned collectSides(const RgMapState& state, const Region& region, const GatewaySegment& door,
                      const DoorSideProbe& probe, Visit visit) {
  const double length = (door.b - door.a).norm();
  if (!(length > 0.0)) return kNoSide;
  const Eigen::Vector2d along = (door.b - door.a) / length;
  const Eigen::Vector2d left(-along.y(), along.x());
  unsigned sides = kNoSide;
  for (DataId id : region.scans) {
    const StoredScan& stored = state.scans.at(id);
    const Eigen::Vector2d offset = Eigen::Vector2d(stored.corrected.x, stored.corrected.y) - door.a;
    const double t = offset.dot(along), n = offset.dot(left);
    if (t < -probe.widenM || t > length + probe.widenM || std::abs(n) > probe.depthM || std::abs(n) < probe.besideLineM)
      continue;
    const unsigned side = n > 0.0 ? kLeftSide : kRightSide;
    if ((sides & side) == 0 && visit(stored)) sides |= side;
    if (sides == kBothSides) break;
  }
  return sides;
}

// Whether the beam of `stored` towards `target` (or a neighbour of it) reaches it.
bool seesPoint(const StoredScan& stored, const Eigen::Vector2d& target, const DoorSideProbe& probe,
               double noReturnFreeRangeM) {
  const LaserScan& scan = stored.scan;
  if (!(std::abs(scan.angleIncrement) > 0.0)) return false;
  const Eigen::Vector2d toTarget = target - Eigen::Vector2d(stored.corrected.x, stored.corrected.y);
  const double distance = toTarget.norm();
  double relative = std::remainder(std::atan2(toTarget.y(), toTarget.x()) - stored.corrected.theta - scan.startAngle,
                                   2.0 * std::numbers::pi);
  if (relative / scan.angleIncrement < -0.5) relative += std::copysign(2.0 * std::numbers::pi, scan.angleIncrement);
  const long beam = std::lround(relative / scan.angleIncrement);
  const bool hasMaxRange = scan.maxRange > 0.0;
  const double noReturnSeen = hasMaxRange ? std::min(noReturnFreeRangeM, scan.maxRange) : noReturnFreeRangeM;
  for (long k = beam - 1; k <= beam + 1; ++k) {
    if (k < 0 || k >= long(scan.ranges.size())) continue;
    const float range = scan.ranges[std::size_t(k)];
    if (!(range > 0.0f)) continue;  // NaN or no range
    const bool measured = std::isfinite(range) && !(hasMaxRange && range >= scan.maxRange);
    if (measured ? double(range) >= distance - probe.rangeToleranceM : distance <= noReturnSeen) return true;
  }
  return false;
}

}  // namespace

void validate(const DoorSideProbe& probe) {
  const std::array<std::pair<double, const char*>, 4> distances{{{probe.depthM, "depthM"},
                                                                 {probe.widenM, "widenM"},
                                                                 {probe.besideLineM, "besideLineM"},
                                                                 {probe.rangeToleranceM, "rangeToleranceM"}}};
  for (const auto& [value, name] : distances)
    if (!std::isfinite(value) || value < 0.0)
      throw ConfigError(std::string("door sides: ") + name + " must be finite and >= 0");
}

unsigned sidesStoodOn(const RgMapState& state, const Region& region, const GatewaySegment& door,
                      const DoorSideProbe& probe) {
  return collectSides(state, region, door, probe, [](const StoredScan&) { return true; });
}

unsigned sidesSeenFrom(const RgMapState& state, const Region& region, const GatewaySegment& door,
                       const DoorSideProbe& probe, double noReturnFreeRangeM) {
  const Eigen::Vector2d midpoint = 0.5 * (door.a + door.b);
  return collectSides(state, region, door, probe, [&](const StoredScan& stored) {
    return seesPoint(stored, midpoint, probe, noReturnFreeRangeM);
  });
}

}  // namespace rgnav
