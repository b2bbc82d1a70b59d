// RangeSanitizer: the per-beam rule and its application to a whole scan.
#include "core/logs/RangeSanitizer.h"

#include <cmath>

#include "core/common/SensorData.h"

namespace rgnav {

float sanitizeRange(double raw, double maxRange, LogStats& stats) {
  if (!std::isfinite(raw) || raw < 0.0) {
    ++stats.droppedRanges;
    return LaserScan::kInvalid;
  }
  if (raw >= maxRange) {
    ++stats.noReturnRanges;
    return LaserScan::kNoReturn;
  }
  return static_cast<float>(raw);
}

void sanitizeRanges(std::span<const double> raw, double maxRange, std::vector<float>& out,
                    LogStats& stats) {
  out.clear();
  out.reserve(raw.size());
  for (const double value : raw) {
    out.push_back(sanitizeRange(value, maxRange, stats));
  }
}

}  // namespace rgnav
