// Narrow passages along a simulated room tour (see TourPassages.h).
#include "tests/eval/doors/TourPassages.h"

#include "core/common/Errors.h"
#include "core/sim/TourRun.h"

namespace rgnav {

TourPassages detectAlongTour(const OccupancyGrid& grid, const GroundTruth& truth, const TourDetectionSetup& setup) {
  if (setup.everyScans == 0) throw InvalidArgumentError("detectAlongTour: everyScans must be at least 1");
  const NarrowPassageDetector detector(setup.detector);
  PassageTracker tracker(setup.tracker);
  SimulationConfig config;
  config.seed = setup.seed;
  TourPassages out;
  std::size_t scans = 0;
  const RoomTour tour = driveRoomTour(grid, truth, config, [&](const SimulationStep& step) {
    if (!step.scan || scans++ % setup.everyScans != 0) return;
    const std::vector<PassageHypothesis> found = detector.detect(*step.scan, step.scan->sensorPose);
    ++out.scansDetected;
    out.path.emplace_back(step.truePose.x, step.truePose.y);
    out.hypotheses += found.size();
    out.traversals += tracker.update(step.scan->id, step.truePose, found).traversals.size();
  });
  out.unreachableRooms = tour.plan.unreachableRooms;
  out.gateways = tracker.gateways();
  return out;
}

}  // namespace rgnav
