// RegionChanges: which regions of a cached RG map the kernel's events since the cached revision
// may have changed in content (line map, freespace, objects and their names: what a region's
// summary does not show), so that the PathPlanning module fetches only those again. Every event
// that names regions marks them; poses revised by the SLAM move every region's content, so they
// mark all. Gateway and cost events change no region's content (gateways and the graph are
// fetched whole at every new revision).
#pragma once

#include <set>
#include <vector>

#include "core/rgmap/kernel/RgMapEvent.h"

namespace rgnav {

struct RegionChanges {
  bool all = false;
  std::set<RegionId> regions;

  bool contains(RegionId id) const { return all || regions.count(id) > 0; }
};

RegionChanges regionChanges(const std::vector<RgMapEvent>& events);

}  // namespace rgnav
