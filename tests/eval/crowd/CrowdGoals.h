// CrowdGoals: the goals of the crowd evaluation: seeded points in the rooms of a world's ground
// truth, each on a free cell at least `clearanceM` from every wall and piece of furniture (so the
// robot fits there with room to turn), in a room other than the previous goal's and at least
// `minSpacingM` from the previous goal (and the first from the start), so every goal is a real
// drive through doors and hallways; optionally only goals a check accepts (reachable on the map).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/raster/OccupancyGrid.h"
#include "core/sim/GroundTruth.h"

namespace rgnav {

struct CrowdGoalOptions {
  int count = 20;
  std::uint64_t seed = 1;
  double clearanceM = 0.7;
  double minSpacingM = 5.0;
};

// Whether the robot may be sent from one point to another (e.g. the planner finds a path on the
// robot's map); candidates it refuses are drawn again.
using GoalCheck = std::function<bool(const Eigen::Vector2d& from, const Eigen::Vector2d& to)>;

// Throws InvalidArgumentError when the world has no cell that qualifies.
std::vector<Eigen::Vector2d> crowdGoals(const OccupancyGrid& grid, const GroundTruth& truth, const Pose2D& start,
                                        const CrowdGoalOptions& options, const GoalCheck& accept = {});

}  // namespace rgnav
