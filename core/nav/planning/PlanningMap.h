// PlanningMap: what route planning needs of an RG map, as the plain values the RG Mapping Kernel
// serves (RgMapViews.h): the regions with their line maps, freespace and objects (region frames),
// the gateways and the RG graph with its learned costs (map frame), and the map revision (the
// kernel's last event ID) that says when cached region grids are stale. The PathPlanning module
// fills it from the kernel's client library, rgnav-plan from an exported .rgmap.json.
#pragma once

#include <vector>

#include "core/rgmap/kernel/RgMapViews.h"

namespace rgnav {

struct PlanningMap {
  std::vector<RegionView> regions;    // ascending ID
  std::vector<GatewayView> gateways;  // the map's gateways (both sides known or not)
  GraphView graph;                    // nodes and edges with learned costs
  RgMapEventId revision = 0;
};

}  // namespace rgnav
