// Plain views of the kernel's map; see RgMapViews.h.
#include "core/rgmap/kernel/RgMapViews.h"

#include "core/common/Errors.h"
#include "core/rgmap/kernel/ObjectNames.h"

namespace rgnav {

RegionSummaryView summaryOf(const Region& r) {
  return {r.id, r.name, r.frame, r.scans.size(), r.finalised, std::vector<GatewayId>(r.gateways.begin(), r.gateways.end())};
}

RegionView regionView(const RgMappingKernel& kernel, RegionId id) {
  const auto found = kernel.state().regions.find(id);
  if (found == kernel.state().regions.end()) throw NotAvailableError("no region " + std::to_string(id.value()));
  RegionView v;
  v.summary = summaryOf(found->second);
  for (const LineSegment& l : kernel.lineMap(id).lines()) v.lines.push_back({l.start, l.end});
  const RegionDescription& d = kernel.description(id);
  if (!d.boundingBox.isEmpty()) {
    v.boxMin = d.boundingBox.min();
    v.boxMax = d.boundingBox.max();
  }
  v.freespace = d.freespace;
  v.areaM2 = d.moments.areaM2;
  v.centroid = d.moments.centroid;
  v.majorAxisAngleRad = d.moments.majorAxisAngleRad;
  v.majorVariance = d.moments.majorVariance;
  v.minorVariance = d.moments.minorVariance;
  v.mainDirections = d.mainDirections;
  v.accuracyInlierShare = d.accuracy.inlierShare;
  v.accuracyRmsM = d.accuracy.rmsDistanceM;
  v.completeness = d.completeness.completeness;
  const std::vector<std::string> names = objectNamesOf(found->second, d.objects);
  for (std::size_t i = 0; i < d.objects.size(); ++i) {
    const Rectangle2D& o = d.objects[i];
    v.objects.push_back({o.pose, o.lengthM, o.widthM, o.confidence, names[i]});
  }
  return v;
}

std::vector<GatewayView> gatewayViews(const RgMappingKernel& kernel) {
  std::vector<GatewayView> out;
  for (const auto& [id, g] : kernel.state().gateways) {
    const PlacedGateway placed = placeGateway(g);
    out.push_back({id, g.record.id, g.record.classes, g.door(), g.neutralised, placed.gatewayPoints,
                   placed.crossingPoints, g.sides[kSideA].region, g.sides[kSideB].region,
                   g.traversalsFrom[0] + g.traversalsFrom[1],
                   {g.sides[kSideA].crossing, g.sides[kSideB].crossing}});
  }
  return out;
}

GraphNodeView nodeView(const RgNode& n) {
  return {n.key.gateway, static_cast<std::size_t>(n.key.side), n.region, n.position};
}

GraphView graphView(const RgGraph& graph) {
  GraphView v;
  for (const RgNode& n : graph.nodes()) v.nodes.push_back(nodeView(n));
  for (const RgEdge& e : graph.edges())
    v.edges.push_back({e.from, e.to, e.gateway, e.region, e.lengthM, e.costM});
  return v;
}

PathView pathView(const RgPath& path) {
  PathView v;
  for (const RgNode& n : path.crossings) v.crossings.push_back(nodeView(n));
  v.costM = path.costM;
  v.lengthM = path.lengthM;
  return v;
}

MapSummaryView mapSummary(const RgMappingKernel& kernel) {
  const RgMapState& s = kernel.state();
  MapSummaryView v;
  v.regions = s.regions.size();
  for (const auto& [id, g] : s.gateways) {
    (g.inMap() ? v.gateways : v.hypotheses) += 1;
    v.neutralised += g.neutralised;
  }
  v.lastScan = s.lastScanId;
  v.lastEvent = s.events.empty() ? 0 : s.events.back().id;
  v.current = s.current;
  return v;
}

}  // namespace rgnav
