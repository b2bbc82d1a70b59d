// rgnav-plan's pictures of a plan (see PlanPicture.h).
#include "tools/plan/PlanPicture.h"

#include "core/rgmap/export/RgMapPng.h"
#include "core/rgmap/export/RgMapSvg.h"

namespace rgnav {
namespace {

constexpr Rgb kPathColour{0, 160, 60};
constexpr Rgb kTargetColour{0, 90, 30};

RegionSnapshot regionSnapshot(const RegionView& v) {
  RegionSnapshot r;
  r.region.id = v.summary.id;
  r.region.frame = v.summary.frame;
  r.region.name = v.summary.name;
  r.region.finalised = v.summary.finalised;
  r.region.gateways = {v.summary.gateways.begin(), v.summary.gateways.end()};
  for (const Segment2& s : v.lines) {
    LineSegment line;
    line.start = s.a;
    line.end = s.b;
    r.lines.push_back(line);
  }
  r.description.freespace = v.freespace;
  r.description.moments.areaM2 = v.areaM2;
  r.description.moments.centroid = v.centroid;
  for (const RectangleObjectView& o : v.objects) r.description.objects.push_back({o.pose, o.lengthM, o.widthM, o.confidence, {}});
  return r;
}

GatewaySnapshot gatewaySnapshot(const GatewayView& v) {
  GatewaySnapshot g;
  g.gateway.id = v.id;
  g.gateway.record.id = v.detectorId;
  g.gateway.record.kind = v.door ? GatewayKind::NarrowPassage : GatewayKind::HallwayArea;
  g.gateway.record.classes = v.classes;
  g.gateway.neutralised = v.neutralised;
  g.gateway.sides[0].region = v.sideA;
  g.gateway.sides[1].region = v.sideB;
  g.inMap = {v.gatewayPoints, v.crossingPoints};
  return g;
}

std::vector<MapPolyline> planOverlays(const PlanRecord& plan) {
  std::vector<Eigen::Vector2d> targets;
  for (const TargetPose& t : plan.plan.targets) targets.push_back({t.pose.x, t.pose.y});
  return {{plan.plan.path, kPathColour, 0.15, 0.0, "plan-path"}, {targets, kTargetColour, 0.0, 0.12, "plan-targets"}};
}

}  // namespace

RgMapSnapshot snapshotOf(const PlanningMap& map) {
  RgMapSnapshot out;
  for (const RegionView& r : map.regions) out.regions.push_back(regionSnapshot(r));
  for (const GatewayView& g : map.gateways) out.gateways.push_back(gatewaySnapshot(g));
  for (const GraphNodeView& n : map.graph.nodes) {
    RgNode node;
    node.key = {n.gateway, n.side == 0 ? GatewaySide::A : GatewaySide::B};
    node.region = n.region;
    node.position = n.position;
    out.graphNodes.push_back(node);
  }
  for (const GraphEdgeView& e : map.graph.edges) {
    RgEdge edge;
    edge.from = e.from;
    edge.to = e.to;
    edge.gateway = e.gateway;
    edge.region = e.region;
    edge.lengthM = e.lengthM;
    edge.costM = e.costM;
    out.graphEdges.push_back(edge);
  }
  out.lastEventId = map.revision;
  return out;
}

void writePlanSvg(const std::string& path, const PlanningMap& map, const PlanRecord& plan) {
  writeRgMapSvg(path, snapshotOf(map), planOverlays(plan));
}

void writePlanPng(const std::string& path, const PlanningMap& map, const PlanRecord& plan) {
  exportRgMapPng(path, snapshotOf(map), 0.05, planOverlays(plan));
}

}  // namespace rgnav
