// RgMappingKernelClient: the RG Map of the RGMappingKernel module: regions with descriptions,
// gateways, the RG graph and paths, names and merges, the map's events by ID, export.
#pragma once

#include <chrono>
#include <vector>

#include "RGMappingKernel.hh"
#include "clientlibs/common/ModuleClient.h"
#include "core/rgmap/kernel/RgMapViews.h"

namespace rgnav {

class RgMappingKernelClient : public ModuleClientOf<RGNav::RGMappingKernel> {
 public:
  explicit RgMappingKernelClient(ClientSettings settings = ClientSettings::fromEnvironment(),
                                 std::string objectName = "RGMappingKernel");

  MapSummaryView summary();
  RegionView currentRegion();
  RegionView region(RegionId id);
  std::vector<RegionSummaryView> regions();
  std::vector<GatewayView> gateways();
  GraphView graph();
  PathView findPath(RegionId startRegion, const Eigen::Vector2d& start, RegionId goalRegion, const Eigen::Vector2d& goal);
  void nameRegion(RegionId id, const std::string& name);
  RegionId regionByName(const std::string& name);
  void nameObject(RegionId region, const Eigen::Vector2d& atInRegion, const std::string& name);
  RgMappingKernel::NamedObject objectByName(const std::string& name);
  RegionId mergeRegions(RegionId a, RegionId b);
  RgMapEventBatch eventsSince(RgMapEventId afterId, std::uint32_t maxCount);
  // The files written, one per line. Describing and drawing a large map takes long (an outdoor
  // campus: tens of seconds), so this call waits up to kExportCallTimeout for its answer.
  std::string exportMap(const std::string& directory, const std::string& name, bool occupancy);

  static constexpr std::chrono::minutes kExportCallTimeout{10};

 private:
  std::string consumer_;
  TypedConnection<RGNav::RGMappingKernel> exports_;  // exportMap only, with the long timeout
};

}  // namespace rgnav
