// Reading a navigation task's keys (see NavigationTask.h).
#include "core/sim/world/NavigationTask.h"

#include "core/config/ConfigNode.h"
#include "core/sim/world/WorldYaml.h"

namespace rgnav {

std::optional<NavigationTask> readNavigationTask(const ConfigNode& root, const OccupancyGrid& grid) {
  const bool hasStart = root.has("start"), hasGoal = root.has("goal");
  if (!hasStart && !hasGoal) {
    if (root.has("reference_path_length_m")) root["reference_path_length_m"].fail("needs start and goal");
    return std::nullopt;
  }
  if (!hasGoal) root["start"].fail("a task needs a goal too");
  if (!hasStart) root["goal"].fail("a task needs a start too");
  NavigationTask task;
  const Eigen::Vector3d start = readPoint3(root["start"]);
  task.start = {start.x(), start.y(), normalizeAngle(start.z())};
  task.goal = readPoint(root["goal"]);
  if (!grid.cellOf({task.start.x, task.start.y})) root["start"].fail("lies outside the map");
  if (!grid.cellOf(task.goal)) root["goal"].fail("lies outside the map");
  if (root.has("reference_path_length_m")) task.referencePathLength = readPositive(root["reference_path_length_m"]);
  if (root.has("cylinders")) task.obstacleCount = static_cast<int>(root["cylinders"].asInteger(0, 1000000));
  return task;
}

}  // namespace rgnav
