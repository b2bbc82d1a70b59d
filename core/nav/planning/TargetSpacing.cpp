// TargetSpacing: target poses along a planned path (see the header).
#include "core/nav/planning/TargetSpacing.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

std::vector<TargetPose> targetsAlong(std::span<const PathLeg> legs, double minSpacingM, double maxSpacingM,
                                     std::optional<double> goalHeading) {
  if (!(minSpacingM > 0.0) || !(maxSpacingM >= minSpacingM))
    throw InvalidArgumentError("target spacing: 0 < minimum <= maximum must hold");
  struct Point {
    Eigen::Vector2d at;
    RegionId region;
    double arc = 0.0;  // distance along the path from the start
  };
  std::vector<Point> kept;
  Eigen::Vector2d last = Eigen::Vector2d::Zero(), lastDirection(1.0, 0.0);
  bool started = false;
  double arc = 0.0, keptArc = 0.0;
  for (const PathLeg& leg : legs) {
    for (std::size_t i = 0; i < leg.points.size(); ++i) {
      const Eigen::Vector2d& p = leg.points[i];
      if (!started) {
        last = p;
        started = true;
        continue;
      }
      const double length = (p - last).norm();
      if (length == 0.0) continue;
      // Even division of the stretch into pieces no longer than the maximum.
      const int pieces = std::max(1, static_cast<int>(std::ceil(length / maxSpacingM - 1e-9)));
      for (int k = 1; k <= pieces; ++k) {
        const Eigen::Vector2d q = last + (p - last) * (double(k) / pieces);
        arc += length / pieces;
        if (arc - keptArc >= minSpacingM) {
          kept.push_back({q, leg.region, arc});
          keptArc = arc;
        }
      }
      lastDirection = p - last;
      last = p;
    }
  }
  if (!started) return {};
  // The goal is always a target. When the last target lies too close to it, the goal replaces
  // that target if the gap to the one before stays within the maximum.
  if (arc > keptArc) {
    if (!kept.empty() && arc - keptArc < minSpacingM) {
      const double before = kept.size() > 1 ? kept[kept.size() - 2].arc : 0.0;
      if (arc - before <= maxSpacingM) kept.pop_back();
    }
    kept.push_back({last, legs.back().region, arc});
  }
  std::vector<TargetPose> out;
  out.reserve(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    double heading;
    if (i + 1 < kept.size()) {
      const Eigen::Vector2d d = kept[i + 1].at - kept[i].at;
      heading = std::atan2(d.y(), d.x());
    } else if (goalHeading) {
      heading = *goalHeading;
    } else {
      heading = std::atan2(lastDirection.y(), lastDirection.x());
    }
    out.push_back({Pose2D{kept[i].at.x(), kept[i].at.y(), normalizeAngle(heading)}, kept[i].region});
  }
  return out;
}

}  // namespace rgnav
