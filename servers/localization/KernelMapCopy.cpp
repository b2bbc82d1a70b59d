// The module's copy of the kernel's map, refreshed region by region (see KernelMapCopy.h).
#include "servers/localization/KernelMapCopy.h"

namespace rgnav {

std::optional<KernelMapChanges> KernelMapCopy::refresh() {
  const MapSummaryView summary = kernel_.summary();
  if (summary_ && *summary_ == summary) return std::nullopt;
  KernelMapChanges changes;
  changes.revision = summary.lastEvent;
  std::map<RegionId, RegionSummaryView> regions;
  for (const RegionSummaryView& s : kernel_.regions()) {
    const auto cached = regions_.find(s.id);
    if (cached != regions_.end() && cached->second == s) {
      regions.emplace(s.id, s);
      continue;
    }
    try {
      changes.regions.push_back(kernel_.region(s.id));
      ++regionsFetched_;
      regions.emplace(s.id, changes.regions.back().summary);  // as fetched (it may be newer than the list)
    } catch (const NotAvailableError&) {
      // merged away since the list was taken: the next refresh says so
    }
  }
  for (const auto& [id, s] : regions_)
    if (regions.count(id) == 0) changes.removed.push_back(id);
  changes.gateways = kernel_.gateways();
  regions_ = std::move(regions);
  summary_ = summary;
  return changes;
}

}  // namespace rgnav
