// RgMappingKernelClient: the RG Map of the RGMappingKernel module: regions with descriptions,
// gateways, the RG graph and paths, names, merges and their undoing, door states, confirmed
// gateway traversals, the map's
// events by ID, export. Names, merges, undoing them and door states are not idempotent: each call
// carries a new random request ID, kept over its retries, so that the kernel acts on it once
// however often a lost answer makes the client ask (RGMappingKernel.idl). Errors:
// BadArgumentError naming the field, NotAvailableError, ModuleFailedError,
// ModuleUnavailableError (ClientConnection.h).
#pragma once

#include <chrono>
#include <random>
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
  // Regions that share no gateway are refused (InvalidArgumentError) unless `force`.
  RegionId mergeRegions(RegionId a, RegionId b, bool force = false);
  // Undoes the latest kept merge on request that made `merged`; returns the restored region
  // (InvalidArgumentError if there is none or the map changed since, RGMappingKernel.idl).
  RegionId unmergeRegions(RegionId merged);
  // The door of gateway `door` was found open (traversable) or blocked (thesis 5.4). `request` 0
  // makes a new request ID; a module that relays a request of its own passes that ID on, so that
  // the kernel acts once however often the relayed request is retried.
  void reportDoorState(GatewayId door, bool traversable, std::uint64_t request = 0);
  // The robot was confirmed to have passed `gateway` from region `from` into `to` at scan
  // `scanId` (the Localization module's evidence); the kernel counts it once per request.
  void reportTraversal(GatewayId gateway, RegionId from, RegionId to, DataId scanId);
  RgMapEventBatch eventsSince(RgMapEventId afterId, std::uint32_t maxCount);
  // The files written, one per line; `directory` is relative to the kernel's export root (""
  // for the root) or absolute inside it (RGMappingKernel.idl). Describing and drawing a large map takes long (an outdoor
  // campus: tens of seconds), so this call waits up to kExportCallTimeout for its answer.
  std::string exportMap(const std::string& directory, const std::string& name, bool occupancy);

  static constexpr std::chrono::minutes kExportCallTimeout{10};

 private:
  using RequestId = std::uint64_t;
  RequestId newRequestId();  // nonzero

  std::string consumer_;
  TypedConnection<RGNav::RGMappingKernel> exports_;  // exportMap only, with the long timeout
  std::mt19937_64 requestIds_;
};

}  // namespace rgnav
