// RangeSanitizer: converts raw beam values of a log to the REP-117 range convention of LaserScan
// (NaN = dropped, +inf = no return) and counts both kinds into LogStats.
#pragma once

#include <span>
#include <vector>

#include "core/logs/LogStats.h"

namespace rgnav {

// NaN, infinite or negative -> NaN (counted as dropped); >= maxRange -> +inf (counted as no
// return); anything else is kept.
float sanitizeRange(double raw, double maxRange, LogStats& stats);

// Replaces `out` with the sanitized `raw` beams.
void sanitizeRanges(std::span<const double> raw, double maxRange, std::vector<float>& out,
                    LogStats& stats);

}  // namespace rgnav
