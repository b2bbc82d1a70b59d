// KernelMapCopy: the Localization module's copy of the RG Mapping Kernel's map, kept up to date
// through the kernel's client library. refresh() asks only for the map summary; when it changed
// (an event, or scans stacked into a region), it fetches the region summaries and, of the
// regions, only those that are new or whose summary changed (scan count, frame, gateways), and
// the gateways (a short list). Thesis 5.3 has the module request only the current region and its
// neighbours; this copy holds every region (acceptable for floors of the thesis' size: a region
// is a few kB; the likelihood fields are built only for the regions particles are in).
#pragma once

#include <map>
#include <optional>
#include <vector>

#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"

namespace rgnav {

struct KernelMapChanges {
  std::vector<RegionView> regions;   // new or changed, fetched anew
  std::vector<RegionId> removed;     // gone from the kernel's map (merged away)
  std::vector<GatewayView> gateways;  // all of the kernel's gateways
  RgMapEventId revision = 0;          // the kernel's last event
};

class KernelMapCopy {
 public:
  explicit KernelMapCopy(RgMappingKernelClient& kernel) : kernel_(kernel) {}

  // The changes since the last refresh; nullopt when the summary did not change. Throws what the
  // client throws (ModuleUnavailableError when the kernel does not answer).
  std::optional<KernelMapChanges> refresh();
  std::size_t regionsFetched() const { return regionsFetched_; }
  // Every scan up to this one is in the map as of the last refresh (MapSummaryView::lastScan).
  DataId mappedScan() const { return summary_ ? summary_->lastScan : 0; }

 private:
  RgMappingKernelClient& kernel_;
  std::optional<MapSummaryView> summary_;
  std::map<RegionId, RegionSummaryView> regions_;  // as of the last refresh
  std::size_t regionsFetched_ = 0;
};

}  // namespace rgnav
