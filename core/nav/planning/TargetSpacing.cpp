// TargetSpacing: target poses along a planned path (see the header).
#include "core/nav/planning/TargetSpacing.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

std::vector<Pose2D> targetsAlong(std::span<const Eigen::Vector2d> path, double minSpacingM, double maxSpacingM,
                                 std::optional<double> goalHeading) {
  if (!(minSpacingM > 0.0) || !(maxSpacingM >= minSpacingM))
    throw InvalidArgumentError("target spacing: 0 < minimum <= maximum must hold");
  if (path.empty()) return {};
  struct Point {
    Eigen::Vector2d at;
    double arc = 0.0;  // distance along the path from the start
  };
  std::vector<Point> kept;
  Eigen::Vector2d last = path.front(), lastDirection(1.0, 0.0);
  double arc = 0.0, keptArc = 0.0;
  for (const Eigen::Vector2d& p : path.subspan(1)) {
    const double length = (p - last).norm();
    if (length == 0.0) continue;
    // Even division of the stretch into pieces no longer than the maximum.
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / maxSpacingM - 1e-9)));
    for (int k = 1; k <= pieces; ++k) {
      arc += length / pieces;
      if (arc - keptArc >= minSpacingM) {
        kept.push_back({last + (p - last) * (double(k) / pieces), arc});
        keptArc = arc;
      }
    }
    lastDirection = p - last;
    last = p;
  }
  if (arc > keptArc) {
    if (!kept.empty() && arc - keptArc < minSpacingM) {
      const double before = kept.size() > 1 ? kept[kept.size() - 2].arc : 0.0;
      if (arc - before <= maxSpacingM) kept.pop_back();
    }
    kept.push_back({last, arc});
  }
  std::vector<Pose2D> out;
  out.reserve(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    Eigen::Vector2d direction = lastDirection;
    if (i + 1 < kept.size()) direction = kept[i + 1].at - kept[i].at;
    const double heading = i + 1 == kept.size() && goalHeading ? *goalHeading : std::atan2(direction.y(), direction.x());
    out.push_back({kept[i].at.x(), kept[i].at.y(), normalizeAngle(heading)});
  }
  return out;
}

}  // namespace rgnav
