// An IPA floor plan mapped by the room tour, as views (see MappedFloor.h).
#include "tests/eval/globalloc/MappedFloor.h"

#include "tests/eval/rooms/MappingRun.h"

namespace rgnav {

MappedFloor mapFloor(const std::string& floorPlanPath, const std::optional<HmmClassifier>& classifier) {
  MappedFloor floor;
  floor.world = loadWorld(floorPlanPath);
  if (!floor.world.truth) throw FileError(floorPlanPath + ": no ground-truth rooms beside it");
  MappingRunSetup setup;
  setup.pipeline = shippedPipelineConfig();
  setup.atEnd = [&](const RgMappingKernel& kernel) {
    for (const auto& [id, region] : kernel.state().regions) floor.regions.push_back(regionView(kernel, id));
    floor.gateways = gatewayViews(kernel);
  };
  floor.mapToWorld = mapRoomTour(floor.world.grid, *floor.world.truth, setup, classifier).mapToWorld;
  return floor;
}

}  // namespace rgnav
