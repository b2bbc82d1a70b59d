// The RG Graph of an RG Map; see RgMapGraph.h.
#include "core/rgmap/kernel/RgMapGraph.h"

#include "core/rgmap/kernel/GatewayGeometry.h"

namespace rgnav {

RgGraphSpec graphSpec(const RgMapState& state) {
  RgGraphSpec spec;
  for (const auto& [id, region] : state.regions) spec.regions.push_back(id);
  for (const auto& [id, g] : state.gateways) {
    const GatewaySideRef& a = g.sides[kSideA];
    const GatewaySideRef& b = g.sides[kSideB];
    if (a.region.isNone() || b.region.isNone()) continue;
    const PlacedGateway placed = placeGateway(g);
    spec.gateways.push_back(
        {id, g.door(), {a.region, placed.crossingPoints[a.crossing]}, {b.region, placed.crossingPoints[b.crossing]}});
  }
  return spec;
}

EdgeCostTable costTable(const RgMapState& state, const EdgeCostConfig& config) {
  EdgeCostTable table(config);
  for (const auto& [edge, stats] : state.edgeTraversals) table.restoreTraversal(edge, stats);
  for (const auto& [gateway, offset] : state.doorOffsets) table.restoreDoorOffset(gateway, offset);
  return table;
}

void storeCosts(RgMapState& state, const EdgeCostTable& table) {
  state.edgeTraversals = table.traversals();
  state.doorOffsets = table.doorOffsets();
}

}  // namespace rgnav
