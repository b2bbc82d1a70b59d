// TourPlanner: reachability, visiting points, and the greedy chain of planner legs.
#include "core/nav/grid/TourPlanner.h"

#include <cstddef>

#include "core/common/Errors.h"

namespace rgnav {

Tour planTour(const OccupancyGrid& grid, std::span<const int> cellRooms, int roomCount, const Pose2D& start,
              const GridPlannerConfig& config) {
  if (cellRooms.size() != grid.cells().size() || roomCount < 0) {
    throw InvalidArgumentError("planTour: the rooms need one entry per grid cell and a non-negative room count");
  }
  const GridPlanner planner(grid, config);
  const WorldPoint startPoint{start.x, start.y};
  const std::vector<bool> reachable = planner.reachableFrom(startPoint);

  // Per room, the reachable cell with the largest clearance (first in row-major order on ties).
  std::vector<CellIndex> best(static_cast<std::size_t>(roomCount));
  std::vector<double> bestClearance(best.size(), -1.0);
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const CellIndex c{col, row};
      const std::size_t index = rowMajor(c, grid.width());
      const int room = cellRooms[index];
      if (room < 0 || room >= roomCount || !reachable[index]) {
        continue;
      }
      const double clearance = planner.clearance().at(c);
      if (clearance > bestClearance[static_cast<std::size_t>(room)]) {
        bestClearance[static_cast<std::size_t>(room)] = clearance;
        best[static_cast<std::size_t>(room)] = c;
      }
    }
  }

  Tour tour;
  std::vector<CellIndex> goals;
  std::vector<int> goalRooms;
  for (int room = 0; room < roomCount; ++room) {
    if (bestClearance[static_cast<std::size_t>(room)] < 0.0) {
      tour.unreachableRooms.push_back(room);
    } else {
      goals.push_back(best[static_cast<std::size_t>(room)]);
      goalRooms.push_back(room);
    }
  }

  tour.route.push_back(startPoint);
  WorldPoint here = startPoint;
  while (!goals.empty()) {
    // Every goal is connected to the start, so a leg always exists.
    const auto leg = planner.planToNearest(here, goals);
    if (!leg) {
      throw Error("planTour: a reachable room could not be reached (internal inconsistency)");
    }
    tour.route.insert(tour.route.end(), leg->waypoints.begin() + 1, leg->waypoints.end());
    here = grid.center(goals[leg->goal]);
    tour.visits.push_back({goalRooms[leg->goal], here, tour.route.size() - 1});
    goals.erase(goals.begin() + static_cast<std::ptrdiff_t>(leg->goal));
    goalRooms.erase(goalRooms.begin() + static_cast<std::ptrdiff_t>(leg->goal));
  }
  return tour;
}

}  // namespace rgnav
