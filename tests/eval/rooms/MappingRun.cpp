// A room tour mapped in process; see MappingRun.h.
#include "tests/eval/rooms/MappingRun.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace rgnav {

WorldPlacement placeInWorld(const std::vector<Pose2D>& corrected, const std::vector<Pose2D>& truePoses) {
  WorldPlacement out;
  out.mapToWorld = compose(truePoses.front(), inverse(corrected.front()));
  for (std::size_t i = 0; i < truePoses.size(); ++i) {
    const Pose2D placed = compose(out.mapToWorld, corrected[i]);
    const double error = std::hypot(placed.x - truePoses[i].x, placed.y - truePoses[i].y);
    out.errors.meanM += error / double(truePoses.size());
    out.errors.maxM = std::max(out.errors.maxM, error);
  }
  return out;
}

MappingRun mapRoomTour(const OccupancyGrid& grid, const GroundTruth& truth, const MappingRunSetup& setup,
                       const std::optional<HmmClassifier>& classifier) {
  using Clock = std::chrono::steady_clock;
  MappingPipeline pipeline(setup.pipeline, classifier);
  MappingRun out;
  std::vector<Pose2D> truePoses;
  Clock::duration busy{};
  const RoomTour tour = driveRoomTour(
      grid, truth, setup.simulation,
      [&](const SimulationStep& step) {
        if (!step.scan) return;
        LaserScan scan = *step.scan;
        scan.sensorPose = scan.odometry;
        truePoses.push_back(step.truePose);
        out.truePath.emplace_back(step.truePose.x, step.truePose.y);
        const auto started = Clock::now();
        if (setup.truePoses)
          pipeline.addScanAt(scan, step.truePose);
        else
          pipeline.addScan(scan);
        busy += Clock::now() - started;
      },
      setup.maxTourSeconds);
  const auto started = Clock::now();
  pipeline.finish();
  out.map = finalMapOf(pipeline.kernel());
  busy += Clock::now() - started;
  if (setup.atEnd) setup.atEnd(pipeline.kernel());
  out.mappingSeconds = std::chrono::duration<double>(busy).count();
  if (!truePoses.empty()) {
    std::vector<Pose2D> corrected;
    for (std::size_t i = 0; i < truePoses.size(); ++i) corrected.push_back(pipeline.correctedPose(DataId(i + 1)));
    const WorldPlacement placement = placeInWorld(corrected, truePoses);
    out.mapToWorld = placement.mapToWorld;
    out.poseErrors = placement.errors;
  }
  for (const auto& [id, region] : pipeline.kernel().state().regions) out.regionScans[id] = region.scans;
  out.tour = tour.run;
  out.unreachableRooms = tour.plan.unreachableRooms;
  out.counts = pipeline.counts();
  return out;
}

}  // namespace rgnav
