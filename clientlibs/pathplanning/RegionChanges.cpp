// The regions an RG map's events may have changed (see RegionChanges.h).
#include "clientlibs/pathplanning/RegionChanges.h"

namespace rgnav {

RegionChanges regionChanges(const std::vector<RgMapEvent>& events) {
  using K = RgMapEventKind;
  RegionChanges out;
  for (const RgMapEvent& e : events) {
    switch (e.kind) {
      case K::PosesRevised:
        out.all = true;
        break;
      case K::GatewayAdded:
      case K::GatewayUpdated:
      case K::GatewayDropped:
      case K::CostsLearned:
        break;
      default:
        for (const RegionId r : {e.region, e.other})
          if (!r.isNone()) out.regions.insert(r);
    }
  }
  return out;
}

}  // namespace rgnav
