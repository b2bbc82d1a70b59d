// Seeded goals in the rooms of a world (see CrowdGoals.h).
#include "tests/eval/crowd/CrowdGoals.h"

#include <map>
#include <random>

#include "core/common/Errors.h"
#include "core/nav/grid/ClearanceMap.h"

namespace rgnav {

std::vector<Eigen::Vector2d> crowdGoals(const OccupancyGrid& grid, const GroundTruth& truth, const Pose2D& start,
                                        const CrowdGoalOptions& options, const GoalCheck& accept) {
  const ClearanceMap clearance(grid);
  std::map<int, std::vector<Eigen::Vector2d>> roomCells;  // room -> qualifying cell centres
  for (int row = 0; row < grid.height(); ++row)
    for (int col = 0; col < grid.width(); ++col) {
      const CellIndex c{col, row};
      if (grid.blocked(c) || clearance.at(c) < options.clearanceM) continue;
      const WorldPoint p = grid.center(c);
      const int room = truth.roomAt(p);
      if (room >= 0) roomCells[room].emplace_back(p.x, p.y);
    }
  if (roomCells.size() < 2) throw InvalidArgumentError("fewer than two rooms have space for a goal");
  std::vector<int> rooms;
  for (const auto& [room, cells] : roomCells) rooms.push_back(room);

  std::mt19937_64 random(options.seed);
  std::vector<Eigen::Vector2d> goals;
  Eigen::Vector2d previous(start.x, start.y);
  int previousRoom = truth.roomAt({start.x, start.y});
  for (int attempt = 0; static_cast<int>(goals.size()) < options.count; ++attempt) {
    if (attempt > 100000) throw InvalidArgumentError("no acceptable goal far enough from the previous one");
    const int room = rooms[std::uniform_int_distribution<std::size_t>(0, rooms.size() - 1)(random)];
    if (room == previousRoom) continue;
    const auto& cells = roomCells[room];
    const Eigen::Vector2d goal = cells[std::uniform_int_distribution<std::size_t>(0, cells.size() - 1)(random)];
    if ((goal - previous).norm() < options.minSpacingM) continue;
    if (accept && !accept(previous, goal)) continue;
    goals.push_back(goal);
    previous = goal;
    previousRoom = room;
  }
  return goals;
}

}  // namespace rgnav
