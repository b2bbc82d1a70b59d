// NavigationTask: a world that comes with a job for the robot: where it starts, where it must go,
// and (BARN benchmark, see ../shared/data/planning/barn/SOURCES.md) the length of the benchmark's
// reference path, from which the benchmark's optimal time follows. Read from the extra keys of a
// map_server YAML (MapServerYaml.h):
//   start: [x, y, yaw]              # m, m, rad; required with goal
//   goal: [x, y]                    # m; required with start
//   reference_path_length_m: 13.4   # optional, positive
//   cylinders: 209                  # optional, how many obstacles the world has (informational)
#pragma once

#include <optional>

#include "core/common/Pose2D.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

class ConfigNode;

struct NavigationTask {
  Pose2D start;
  WorldPoint goal;
  std::optional<double> referencePathLength;  // m
  std::optional<int> obstacleCount;
};

// The task keys of a map_server YAML document (nullopt if it has neither start nor goal).
// ConfigError naming the key for a start without a goal (or the reverse), malformed values, or a
// start or goal outside `grid`.
std::optional<NavigationTask> readNavigationTask(const ConfigNode& root, const OccupancyGrid& grid);

}  // namespace rgnav
