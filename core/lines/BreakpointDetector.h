// BreakpointDetector: cuts the point sequence of one scan where the depth jumps, so that no line
// bridges two objects. Adaptive breakpoint detector of Borges & Aldon (2004): consecutive
// points p(n-1), p(n) whose beams lie dphi apart are split if
//     |p(n) - p(n-1)| > r(n-1) * sin(dphi) / sin(lambda - dphi) + 3 * sigma_r,
// i.e. the jump is longer than a surface seen at the grazing angle lambda could explain.
// The thesis (5.2) leaves line extraction to the ScanStudio library; this is our choice.
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/lines/ScanPoints.h"

namespace rgnav {

struct BreakpointParams {
  double lambdaRad = 10.0 * M_PI / 180.0;  // worst incidence angle of a surface still seen as one
  double rangeSigmaM = 0.01;               // range noise of the sensor
};

template <class V>
void describe(V& v, BreakpointParams& c) {
  v.degrees("lambda_deg", c.lambdaRad);
  v.field("range_sigma_m", c.rangeSigmaM);
}

// Half-open index ranges [first, second) of `points` between breakpoints, in order.
// `angleIncrementRad` is the scan's beam spacing. Throws InvalidArgumentError for bad params.
std::vector<std::pair<std::size_t, std::size_t>> splitAtBreakpoints(const std::vector<ScanPoint>& points,
                                                                    double angleIncrementRad,
                                                                    const BreakpointParams& params);

}  // namespace rgnav
