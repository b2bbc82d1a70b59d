// selectBeams (ScanBeams.h): an even stride over the scan's beams.
#include "core/nav/localization/ScanBeams.h"

#include <cmath>

namespace rgnav {

ScanBeams selectBeams(const LaserScan& scan, const BeamModelConfig& config) {
  ScanBeams beams;
  const std::size_t n = scan.ranges.size();
  if (n == 0) return beams;
  const double step = std::max(1.0, static_cast<double>(n) / static_cast<double>(config.beams));
  const double maxRange = std::min(config.maxRangeM, scan.maxRange > 0.0 ? scan.maxRange : config.maxRangeM);
  beams.endpoints.reserve(config.beams);
  for (double k = step / 2.0; k < static_cast<double>(n); k += step) {
    const std::size_t i = static_cast<std::size_t>(k);
    const double r = scan.ranges[i];
    if (!std::isfinite(r) || r <= 0.0 || r >= maxRange) continue;
    const double a = scan.startAngle + static_cast<double>(i) * scan.angleIncrement;
    beams.endpoints.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return beams;
}

}  // namespace rgnav
