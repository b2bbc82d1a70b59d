// The kernel's map, cached by revision (see KernelMapCache.h).
#include "clientlibs/pathplanning/KernelMapCache.h"

#include "clientlibs/pathplanning/RegionChanges.h"

namespace rgnav {
namespace {

constexpr std::uint32_t kEventBatch = 500;

// The events after `after` up to `latest`.
std::vector<RgMapEvent> eventsBetween(RgMappingKernelClient& kernel, RgMapEventId after, RgMapEventId latest) {
  std::vector<RgMapEvent> out;
  while (after < latest) {
    const RgMapEventBatch batch = kernel.eventsSince(after, kEventBatch);
    if (batch.events.empty()) break;
    out.insert(out.end(), batch.events.begin(), batch.events.end());
    after = batch.events.back().id;
  }
  return out;
}

}  // namespace

bool KernelMapCache::refresh() {
  const MapSummaryView summary = kernel_.summary();
  if (filled_ && summary.lastEvent == revision_ && summary.lastScan == lastScan_) return false;
  RegionChanges changes;
  if (filled_ && summary.lastEvent > revision_) {
    changes = regionChanges(eventsBetween(kernel_, revision_, summary.lastEvent));
  } else {
    changes.all = true;  // the first fetch, or a kernel whose map went back (restored from an older checkpoint)
  }
  std::map<RegionId, RegionView> regions;
  for (const RegionSummaryView& s : kernel_.regions()) {
    const auto cached = regions_.find(s.id);
    if (cached != regions_.end() && cached->second.summary == s && !changes.contains(s.id)) {
      regions.emplace(s.id, std::move(cached->second));
      continue;
    }
    try {
      regions.emplace(s.id, kernel_.region(s.id));
      ++regionsFetched_;
    } catch (const NotAvailableError&) {
      // merged or removed since the list was taken: the next revision says so
    }
  }
  regions_ = std::move(regions);
  gateways_ = kernel_.gateways();
  graph_ = kernel_.graph();
  revision_ = summary.lastEvent;
  lastScan_ = summary.lastScan;
  filled_ = true;
  return true;
}

PlanningMap KernelMapCache::map() const {
  PlanningMap out;
  for (const auto& [id, region] : regions_) out.regions.push_back(region);
  out.gateways = gateways_;
  out.graph = graph_;
  out.revision = revision_;
  return out;
}

}  // namespace rgnav
