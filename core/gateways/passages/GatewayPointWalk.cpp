// The thesis' walk between gateway points (see GatewayPointWalk.h).
#include "core/gateways/passages/GatewayPointWalk.h"

#include <algorithm>

#include "core/gateways/passages/ScanBeams.h"

namespace rgnav {
namespace {

// A beam between two consecutive valid points that got no return within the maximum range.
bool noReturnBetween(const LaserScan& scan, std::size_t beamA, std::size_t beamB) {
  for (std::size_t beam = std::min(beamA, beamB) + 1; beam < std::max(beamA, beamB); ++beam)
    if (isNoReturn(scan, beam)) return true;
  return false;
}

}  // namespace

std::optional<std::size_t> walkToOpening(const LaserScan& scan, const std::vector<ScanPoint>& points,
                                         std::size_t from, std::size_t towards, double minWidthM) {
  const std::ptrdiff_t step = from < towards ? 1 : -1;
  for (std::size_t i = from; i != towards; i = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + step)) {
    if ((points[i].position - points[towards].position).norm() <= minWidthM) return std::nullopt;
    const ScanPoint& next = points[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + step)];
    if ((next.position - points[i].position).norm() >= minWidthM || noReturnBetween(scan, points[i].beam, next.beam))
      return i;
  }
  return std::nullopt;
}

}  // namespace rgnav
