// Wandering to random goals with the simulator's tour driver (see RandomGoalDriver.h).
#include "tests/eval/globalloc/RandomGoalDriver.h"

#include "core/common/Errors.h"

namespace rgnav {

RandomGoalDriver::RandomGoalDriver(const GridPlanner& planner, const std::vector<bool>& reachable, std::uint64_t seed)
    : planner_(planner), rng_(seed) {
  const OccupancyGrid& grid = planner.grid();
  for (int row = 0; row < grid.height(); ++row)
    for (int col = 0; col < grid.width(); ++col)
      if (reachable[std::size_t(row) * std::size_t(grid.width()) + std::size_t(col)]) cells_.push_back({col, row});
  if (cells_.empty()) throw InvalidArgumentError("RandomGoalDriver: no reachable cell");
}

WorldPoint RandomGoalDriver::randomPoint() {
  return planner_.grid().center(cells_[std::uniform_int_distribution<std::size_t>(0, cells_.size() - 1)(rng_)]);
}

VelocityCommand RandomGoalDriver::command(const Pose2D& truePose, Timestamp now) {
  for (int attempt = 0; (!leg_ || leg_->finished()) && attempt < 20; ++attempt) try {
      const WorldPoint goal = randomPoint();
      Tour tour;
      tour.route = planner_.plan({truePose.x, truePose.y}, goal);
      tour.visits.push_back({-1, goal, tour.route.size() - 1});
      leg_ = std::make_unique<TourDriver>(std::move(tour), PurePursuitConfig{}, 20.0);
    } catch (const Error&) {
      leg_.reset();
    }
  return leg_ && !leg_->finished() ? leg_->command(truePose, now) : VelocityCommand{};
}

}  // namespace rgnav
