// TargetSpacing: cuts a planned path into the intermediate target poses the collision avoidance
// drives to (thesis 5.5.3: "the distance between intermediate target poses lies between 0.5 and
// 2 meters"). Every corner of the path is a target unless it lies closer than the minimum spacing
// (along the path) to the previous target, and straight stretches longer than the maximum spacing
// are divided evenly. Where a corner is dropped the straight line between the targets cuts it by
// less than the minimum spacing; the path polyline keeps the exact geometry. A target's heading is
// the direction to the next target; the goal keeps the heading of the last stretch unless one is
// given. The goal is always the last target; when the last corner before it lies too close, the
// goal replaces that corner if the gap to the target before stays within the maximum.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

#include "core/common/Pose2D.h"

namespace rgnav {

// Targets along `path` (start first; the start itself is not a target). Throws
// InvalidArgumentError for spacings with 0 < min <= max not holding.
std::vector<Pose2D> targetsAlong(std::span<const Eigen::Vector2d> path, double minSpacingM, double maxSpacingM,
                                 std::optional<double> goalHeading);

}  // namespace rgnav
