// The final map of an in-process kernel; see FinalMap.h.
#include "tests/eval/rooms/FinalMap.h"

namespace rgnav {

FinalMap finalMapOf(const RgMappingKernel& kernel) {
  FinalMap map;
  for (const auto& [id, region] : kernel.state().regions) map.regions.push_back(regionView(kernel, id));
  map.gateways = gatewayViews(kernel);
  map.summary = mapSummary(kernel);
  return map;
}

}  // namespace rgnav
