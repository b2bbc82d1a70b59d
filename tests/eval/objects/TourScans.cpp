// Driving the room tour and keeping its scans by room; see TourScans.h.
#include "tests/eval/objects/TourScans.h"

#include "core/nav/grid/GridPlanner.h"

namespace rgnav {

TourScans scanTour(const OccupancyGrid& grid, const GroundTruth& truth, std::uint64_t seed) {
  SimulationConfig config;
  config.seed = seed;
  TourScans out;
  out.byRoom.resize(static_cast<std::size_t>(truth.roomCount));
  int room = -1;
  const RoomTour tour = driveRoomTour(grid, truth, config, [&](const SimulationStep& step) {
    if (const int here = truth.roomAt({step.truePose.x, step.truePose.y}); here >= 0) room = here;
    if (step.scan && room >= 0) out.byRoom[static_cast<std::size_t>(room)].push_back(*step.scan);
  });
  out.reachable = GridPlanner(grid).reachableFrom({tour.start.x, tour.start.y});
  out.run = tour.run;
  return out;
}

}  // namespace rgnav
