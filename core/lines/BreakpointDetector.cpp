// Adaptive breakpoint detection; see BreakpointDetector.h.
#include "core/lines/BreakpointDetector.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

std::vector<std::pair<std::size_t, std::size_t>> splitAtBreakpoints(const std::vector<ScanPoint>& points,
                                                                    double angleIncrementRad,
                                                                    const BreakpointParams& params) {
  if (!(params.lambdaRad > 0.0 && params.lambdaRad < M_PI / 2) || !(params.rangeSigmaM >= 0.0))
    throw InvalidArgumentError("breakpoint detector: lambda must lie in (0, 90) degrees, sigma >= 0");
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  std::size_t first = 0;
  for (std::size_t n = 1; n <= points.size(); ++n) {
    bool cut = n == points.size();
    if (!cut) {
      const double dphi = double(points[n].beam - points[n - 1].beam) * std::fabs(angleIncrementRad);
      const double jump = (points[n].position - points[n - 1].position).norm();
      cut = dphi >= params.lambdaRad ||
            jump > points[n - 1].rangeM * std::sin(dphi) / std::sin(params.lambdaRad - dphi) + 3.0 * params.rangeSigmaM;
    }
    if (cut) {
      if (n > first) runs.emplace_back(first, n);
      first = n;
    }
  }
  return runs;
}

}  // namespace rgnav
