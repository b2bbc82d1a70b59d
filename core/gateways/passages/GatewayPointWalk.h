// walkToOpening: the validity walk of thesis 4.2.1 (figure 4.10). Starting at one gateway point,
// step through the scan points towards the opposite one "as long as the distance between
// consecutive measurements is below D_lr^min and the distance to the opposite gateway point is
// still large enough (> D_lr^min)". The walk ends either at an opening (a jump of at least
// D_lr^min to the next point, or a beam without return in between: the scan sees past the
// surface there), whose near side is an additional gateway-point candidate, or by coming within
// D_lr^min of the opposite point along one continuous surface, which makes the passage invalid.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/common/SensorData.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {

// `points` are the valid points of `scan` in beam order (scanPoints); `from` and `towards` index
// them. Returns the index of the last point before the opening, or nullopt for no opening.
std::optional<std::size_t> walkToOpening(const LaserScan& scan, const std::vector<ScanPoint>& points,
                                         std::size_t from, std::size_t towards, double minWidthM);

}  // namespace rgnav
