// Driving a whole room tour in the simulation (see TourRun.h).
#include "core/sim/TourRun.h"

#include <cmath>

#include "core/sim/GroundTruthTour.h"
#include "core/sim/StartPose.h"

namespace rgnav {

TourRunResult runTour(Simulation& simulation, TourDriver& driver, const GroundTruth& truth, const StepSink& sink,
                      double maxSeconds) {
  TourRunResult result;
  const Timestamp start = simulation.time();
  while (!driver.finished() && simulation.time() - start <= maxSeconds) {
    simulation.command(driver.command(simulation.truePose(), simulation.time()));
    const Pose2D before = simulation.truePose();
    const SimulationStep step = simulation.step();
    result.distance += std::hypot(step.truePose.x - before.x, step.truePose.y - before.y);
    result.scans += step.scan.has_value();
    if (const int room = truth.roomAt({step.truePose.x, step.truePose.y}); room >= 0) result.roomsEntered.insert(room);
    sink(step);
  }
  result.roomsVisited = driver.roomsVisited();
  result.roomsMissed = driver.roomsMissed();
  const auto& visits = driver.tour().visits;
  for (std::size_t i = result.roomsVisited.size() + result.roomsMissed.size(); i < visits.size(); ++i)
    result.roomsMissed.push_back(visits[i].room);
  result.finished = result.roomsMissed.empty();
  result.collisions = simulation.robotCollisions();
  result.seconds = simulation.time() - start;
  return result;
}

RoomTour driveRoomTour(const OccupancyGrid& grid, const GroundTruth& truth, const SimulationConfig& config,
                       const StepSink& sink, double maxSeconds) {
  RoomTour tour;
  tour.start = openestPose(grid);
  tour.plan = planTour(grid, truth, tour.start);
  Simulation simulation(grid, config, tour.start);
  TourDriver driver(tour.plan, PurePursuitConfig{});
  tour.run = runTour(simulation, driver, truth, sink, maxSeconds);
  return tour;
}

}  // namespace rgnav
