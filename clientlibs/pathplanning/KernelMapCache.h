// KernelMapCache: the RG Mapping Kernel's map as a PlanningMap, as the PathPlanning module and
// rgnav-plan take it (regions by ID with their line maps, freespace and objects; gateways; the RG
// graph with its learned costs), fetched through the kernel's client library and cached by map
// revision, the kernel's last event ID (RgMapSummary.lastEvent). refresh() asks only for the
// summary while the revision stays; when it changed, it fetches the region list, the gateways and
// the graph, and again only the regions that are new, whose summary changed, or that an event
// since the cached revision names (RegionChanges.h); all of them when the revision went back (a
// kernel restored from an older checkpoint). Scans stacked into the current region are no event,
// but they grow its freespace (the way on that an exploring robot needs): a summary whose last
// scan moved fetches the regions whose summary changed (the current one) again.
#pragma once

#include <cstddef>
#include <map>

#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"
#include "core/nav/planning/PlanningMap.h"

namespace rgnav {

class KernelMapCache {
 public:
  explicit KernelMapCache(RgMappingKernelClient& kernel) : kernel_(kernel) {}

  // Brings the copy up to the kernel's revision and last scan; true if it changed. Throws what the client
  // throws (ModuleUnavailableError when the kernel does not answer).
  bool refresh();
  // The copy as of the last refresh (regions in ascending ID).
  PlanningMap map() const;
  RgMapEventId revision() const { return revision_; }
  bool empty() const { return regions_.empty(); }
  // Regions fetched since the start: how much the cache saved shows against refreshes.
  std::size_t regionsFetched() const { return regionsFetched_; }

 private:
  RgMappingKernelClient& kernel_;
  bool filled_ = false;
  RgMapEventId revision_ = 0;
  DataId lastScan_ = 0;
  std::map<RegionId, RegionView> regions_;
  std::vector<GatewayView> gateways_;
  GraphView graph_;
  std::size_t regionsFetched_ = 0;
};

}  // namespace rgnav
