// An IPA floor plan mapped by the room tour, as views (see MappedFloor.h).
#include "tests/eval/globalloc/MappedFloor.h"

#include "tests/eval/rooms/MappingRun.h"

namespace rgnav {

MappedFloor mapFloor(const std::string& floorPlanPath, const std::optional<HmmClassifier>& classifier, bool truePoses) {
  MappedFloor floor;
  floor.world = loadWorld(floorPlanPath);
  if (!floor.world.truth) throw FileError(floorPlanPath + ": no ground-truth rooms beside it");
  MappingRunSetup setup;
  setup.pipeline = shippedPipelineConfig();
  setup.truePoses = truePoses;
  std::vector<std::pair<DataId, Eigen::Vector2d>> corrected;
  setup.atEnd = [&](const RgMappingKernel& kernel) {
    for (const auto& [id, region] : kernel.state().regions) floor.regions.push_back(regionView(kernel, id));
    floor.gateways = gatewayViews(kernel);
    for (const auto& [id, scan] : kernel.state().scans) corrected.emplace_back(id, Eigen::Vector2d(scan.corrected.x, scan.corrected.y));
  };
  const MappingRun run = mapRoomTour(floor.world.grid, *floor.world.truth, setup, classifier);
  floor.mapToWorld = run.mapToWorld;
  floor.slamErrorMeanM = run.poseErrors.meanM;
  floor.slamErrorMaxM = run.poseErrors.maxM;
  for (const auto& [id, map] : corrected)
    if (id >= 1 && id <= run.truePath.size()) floor.scans.push_back({run.truePath[std::size_t(id) - 1], map});
  return floor;
}

}  // namespace rgnav
