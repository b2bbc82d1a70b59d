// TargetSpacing: cuts a planned path into the intermediate target poses the collision avoidance
// drives to (thesis 5.5.3: "the distance between intermediate target poses lies between 0.5 and
// 2 meters"). Every corner of the path is a target unless it lies closer than the minimum spacing
// (along the path) to the previous target, and straight stretches longer than the maximum spacing
// are divided evenly. Where a corner is dropped the straight line between the targets cuts it by
// less than the minimum spacing; the path polyline keeps the exact geometry. A target's heading is
// the direction to the next target; the goal keeps the heading of the last stretch unless one is
// given. Every target carries the region of the leg it lies on.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

#include "core/nav/planning/RoutePlanner.h"

namespace rgnav {

struct PathLeg {
  RegionId region;
  std::vector<Eigen::Vector2d> points;  // map frame; the first is the previous leg's last point
};

// Targets along `legs` (the start itself is not a target). Throws InvalidArgumentError for
// spacings with 0 < min <= max not holding.
std::vector<TargetPose> targetsAlong(std::span<const PathLeg> legs, double minSpacingM, double maxSpacingM,
                                     std::optional<double> goalHeading);

}  // namespace rgnav
