// Counting the beams that see beyond a gateway line (see OpenSpaceBehind.h).
#include "core/gateways/passages/OpenSpaceBehind.h"

#include <cmath>

#include "core/gateways/passages/ScanBeams.h"

namespace rgnav {

SeeThrough seeThrough(const LaserScan& scan, const ScanPoint& a, const ScanPoint& b, std::size_t firstBeam,
                      std::size_t lastBeam, double depthM) {
  const Eigen::Vector2d along = b.position - a.position;
  Eigen::Vector2d away(-along.y(), along.x());
  away.normalize();
  if (away.dot(a.position) < 0.0) away = -away;  // the normal pointing away from the scanner
  SeeThrough result;
  for (std::size_t beam = firstBeam + 1; beam < lastBeam; ++beam) {
    const double r = scan.ranges[beam];
    if (std::isnan(r) || r <= 0.0) continue;
    ++result.beams;
    if (isNoReturn(scan, beam)) {
      ++result.beyond;
      continue;
    }
    const double bearing = bearingOf(scan, beam);
    const Eigen::Vector2d p(r * std::cos(bearing), r * std::sin(bearing));
    if (away.dot(p - a.position) >= depthM) ++result.beyond;
  }
  return result;
}

}  // namespace rgnav
