// FinalMap: the RG Map at the end of a run as the RG Mapping Kernel module serves it
// (RgMapViews.h: region views with their freespace bitmaps and frames, gateways placed in the map
// frame, the map's counts). The room evaluation scores only this, so the map can come from the
// in-process pipeline (finalMapOf) or, later, from a running server set through the kernel's
// client library, which returns the same view types.
#pragma once

#include <vector>

#include "core/rgmap/kernel/RgMapViews.h"

namespace rgnav {

struct FinalMap {
  std::vector<RegionView> regions;  // ascending ID; freespace in the region frame, frame in the map frame
  std::vector<GatewayView> gateways;  // map frame
  MapSummaryView summary;
};

// Every region of the kernel's map with its final description. Throws what
// RgMappingKernel::description throws.
FinalMap finalMapOf(const RgMappingKernel& kernel);

}  // namespace rgnav
