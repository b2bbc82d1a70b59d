// ApproachTrajectory: straight-line sampling with labels.
#include "core/sim/scenarios/ApproachTrajectory.h"

#include <cmath>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"

namespace rgnav {

Approach makeApproach(GatewayClass gatewayClass, double width, double startDistance,
                      double lateralOffset, double spacing) {
  requirePositive(width, "hallway width");
  requirePositive(spacing, "approach sample spacing");
  if (!std::isfinite(startDistance) || startDistance <= width / 2.0 || !std::isfinite(lateralOffset)) {
    throw ConfigError("approach start distance must lie beyond half the hallway width");
  }
  Approach approach{startDistance, lateralOffset, {}};
  const double end = -width / 2.0;
  const auto samples = static_cast<int>(std::floor((startDistance - width / 2.0) / spacing + 1e-9));
  const auto add = [&](double x) {
    approach.poses.push_back({{x, lateralOffset, 0.0}, gatewayClass, std::hypot(x, lateralOffset)});
  };
  for (int k = 0; k <= samples; ++k) {
    add(-startDistance + k * spacing);
  }
  if (approach.poses.back().pose.x < end - 1e-9) {
    add(end);
  }
  return approach;
}

}  // namespace rgnav
