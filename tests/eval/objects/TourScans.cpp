// Driving the room tour and keeping its scans by room; see TourScans.h.
#include "tests/eval/objects/TourScans.h"

#include "core/sim/StartPose.h"
#include "core/sim/motion/GridPlanner.h"

namespace rgnav {

namespace {
constexpr double kMaxTourSeconds = 4 * 3600.0;  // as rgnav-sim-tour
}  // namespace

TourScans scanTour(const OccupancyGrid& grid, const GroundTruth& truth, std::uint64_t seed) {
  SimulationConfig config;
  config.seed = seed;
  const Pose2D start = openestPose(grid);
  TourScans out;
  out.byRoom.resize(static_cast<std::size_t>(truth.roomCount));
  out.reachable = GridPlanner(grid).reachableFrom({start.x, start.y});
  Simulation simulation(grid, config, start);
  TourDriver driver(planTour(grid, truth, start), PurePursuitConfig{});
  int room = truth.roomAt({start.x, start.y});
  out.run = runTour(
      simulation, driver, truth,
      [&](const SimulationStep& step) {
        if (const int here = truth.roomAt({step.truePose.x, step.truePose.y}); here >= 0) room = here;
        if (step.scan && room >= 0) out.byRoom[static_cast<std::size_t>(room)].push_back(*step.scan);
      },
      kMaxTourSeconds);
  return out;
}

}  // namespace rgnav
