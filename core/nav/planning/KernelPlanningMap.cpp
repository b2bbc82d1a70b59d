// KernelPlanningMap: the kernel's views gathered into a PlanningMap.
#include "core/nav/planning/KernelPlanningMap.h"

namespace rgnav {

PlanningMap planningMapOf(const RgMappingKernel& kernel) {
  PlanningMap map;
  for (const auto& [id, region] : kernel.state().regions) map.regions.push_back(regionView(kernel, id));
  map.gateways = gatewayViews(kernel);
  map.graph = graphView(kernel.graph());
  map.revision = mapSummary(kernel).lastEvent;
  return map;
}

}  // namespace rgnav
