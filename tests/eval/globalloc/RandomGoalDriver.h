// RandomGoalDriver: the robot of a localization trial wandering through a floor: the simulator's
// TourDriver (pure pursuit on the true pose) following a GridPlanner route to a random reachable
// goal, and to the next random goal once it arrived or gave up. The goals come from a seeded
// generator, so a trial drives the same way every time.
#pragma once

#include <memory>
#include <random>
#include <vector>

#include "core/nav/grid/GridPlanner.h"
#include "core/sim/TourDriver.h"

namespace rgnav {

class RandomGoalDriver {
 public:
  // `planner` and `reachable` (row-major over the planner's grid, GridPlanner::reachableFrom)
  // must outlive the driver. InvalidArgumentError if no cell is reachable.
  RandomGoalDriver(const GridPlanner& planner, const std::vector<bool>& reachable, std::uint64_t seed);

  VelocityCommand command(const Pose2D& truePose, Timestamp now);

  // A random reachable free cell's centre.
  WorldPoint randomPoint();

 private:
  const GridPlanner& planner_;
  std::vector<CellIndex> cells_;
  std::mt19937_64 rng_;
  std::unique_ptr<TourDriver> leg_;
};

}  // namespace rgnav
