// TourPlanner: reachability, visiting points, and the greedy chain of planner legs.
#include "core/sim/motion/TourPlanner.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

void requireSameGeometry(const OccupancyGrid& grid, const GroundTruth& truth) {
  const bool same = truth.width == grid.width() && truth.height == grid.height() &&
                    std::abs(truth.resolution - grid.resolution()) < 1e-9 &&
                    std::abs(truth.origin.x - grid.origin().x) < 1e-9 &&
                    std::abs(truth.origin.y - grid.origin().y) < 1e-9 &&
                    truth.labels.size() == grid.cells().size();
  if (!same) {
    throw InvalidArgumentError("planTour: the ground truth does not have the grid's size, resolution and origin");
  }
}

}  // namespace

Tour planTour(const OccupancyGrid& grid, const GroundTruth& truth, const Pose2D& start,
              const GridPlannerConfig& config) {
  requireSameGeometry(grid, truth);
  const GridPlanner planner(grid, config);
  const WorldPoint startPoint{start.x, start.y};
  const std::vector<bool> reachable = planner.reachableFrom(startPoint);

  // Per room, the reachable cell with the largest clearance (first in row-major order on ties).
  std::vector<CellIndex> best(static_cast<std::size_t>(std::max(truth.roomCount, 0)));
  std::vector<double> bestClearance(best.size(), -1.0);
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const CellIndex c{col, row};
      const int room = truth.roomOf(c);
      if (room < 0 || room >= truth.roomCount || !reachable[rowMajor(c, grid.width())]) {
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
  for (int room = 0; room < truth.roomCount; ++room) {
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
