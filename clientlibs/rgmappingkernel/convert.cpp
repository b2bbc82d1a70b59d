// Conversions between RGMappingKernel.idl types and the kernel's plain views (see convert.h).
#include "clientlibs/rgmappingkernel/convert.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/gatewaydetection/convert.h"
#include "core/common/Errors.h"

namespace rgnav {

RGNav::RgNode toIdl(const GraphNodeView& n) {
  return RGNav::RgNode{n.gateway.value(), static_cast<CORBA::ULong>(n.side), n.region.value(), toIdl(n.position)};
}
GraphNodeView fromIdl(const RGNav::RgNode& n) { return {GatewayId(n.gateway), n.side, RegionId(n.region), fromIdl(n.position)}; }

RGNav::RegionSummary toIdl(const RegionSummaryView& s) {
  RGNav::RegionSummary out;
  out.id = s.id.value();
  out.name = s.name.c_str();
  out.frame = toIdl(s.frame);
  out.scans = static_cast<CORBA::ULong>(s.scans);
  out.finalised = s.finalised;
  out.gateways = toIdlSeq<RGNav::GatewayIdSeq>(s.gateways, [](GatewayId id) { return id.value(); });
  return out;
}

RegionSummaryView fromIdl(const RGNav::RegionSummary& s) {
  return {RegionId(s.id), s.name.in(), fromIdl(s.frame), s.scans, static_cast<bool>(s.finalised),
          fromIdlSeq<std::vector<GatewayId>>(s.gateways, [](RGNav::GatewayId id) { return GatewayId(id); })};
}

RGNav::RegionInfo toIdl(const RegionView& r) {
  RGNav::RegionInfo out;
  out.summary = toIdl(r.summary);
  out.lines = toIdlSeq<RGNav::Segment2DSeq>(r.lines, [](const Segment2& s) { return RGNav::Segment2D{toIdl(s.a), toIdl(s.b)}; });
  out.boxMin = toIdl(r.boxMin);
  out.boxMax = toIdl(r.boxMax);
  out.freespace.resolution = r.freespace.resolutionM;
  out.freespace.origin = toIdl(r.freespace.originM);
  out.freespace.width = r.freespace.width;
  out.freespace.height = r.freespace.height;
  out.freespace.bits = toIdlSeq<RGNav::OctetSeq>(r.freespace.bytes, [](std::uint8_t b) { return CORBA::Octet(b); });
  out.area = r.areaM2;
  out.centroid = toIdl(r.centroid);
  out.majorAxisAngle = r.majorAxisAngleRad;
  out.majorVariance = r.majorVariance;
  out.minorVariance = r.minorVariance;
  out.mainDirections = toIdlSeq<RGNav::DirectionSeq>(
      r.mainDirections, [](const MainDirection& d) { return RGNav::Direction{d.angleRad, d.lengthM, d.share}; });
  out.accuracyInlierShare = r.accuracyInlierShare;
  out.accuracyRms = r.accuracyRmsM;
  out.completeness = r.completeness;
  out.objects = toIdlSeq<RGNav::RectangleObjectSeq>(r.objects, [](const RectangleObjectView& o) {
    return RGNav::RectangleObject{toIdl(o.pose), o.lengthM, o.widthM, o.confidence, o.name.c_str()};
  });
  return out;
}

RegionView fromIdl(const RGNav::RegionInfo& r) {
  RegionView out;
  out.summary = fromIdl(r.summary);
  out.lines = fromIdlSeq<std::vector<Segment2>>(r.lines, [](const RGNav::Segment2D& s) { return Segment2{fromIdl(s.a), fromIdl(s.b)}; });
  out.boxMin = fromIdl(r.boxMin);
  out.boxMax = fromIdl(r.boxMax);
  out.freespace.resolutionM = r.freespace.resolution;
  out.freespace.originM = fromIdl(r.freespace.origin);
  out.freespace.width = r.freespace.width;
  out.freespace.height = r.freespace.height;
  out.freespace.bytes = fromIdlSeq<std::vector<std::uint8_t>>(r.freespace.bits, [](CORBA::Octet b) { return std::uint8_t(b); });
  out.areaM2 = r.area;
  out.centroid = fromIdl(r.centroid);
  out.majorAxisAngleRad = r.majorAxisAngle;
  out.majorVariance = r.majorVariance;
  out.minorVariance = r.minorVariance;
  out.mainDirections = fromIdlSeq<std::vector<MainDirection>>(
      r.mainDirections, [](const RGNav::Direction& d) { return MainDirection{d.angle, d.length, d.share}; });
  out.accuracyInlierShare = r.accuracyInlierShare;
  out.accuracyRmsM = r.accuracyRms;
  out.completeness = r.completeness;
  out.objects = fromIdlSeq<std::vector<RectangleObjectView>>(r.objects, [](const RGNav::RectangleObject& o) {
    return RectangleObjectView{fromIdl(o.pose), o.length, o.width, o.confidence, o.name.in()};
  });
  return out;
}

RGNav::NamedObject toIdl(const RgMappingKernel::NamedObject& o) { return {o.region.value(), toIdl(o.namedAt)}; }

RgMappingKernel::NamedObject fromIdl(const RGNav::NamedObject& o) { return {RegionId(o.region), fromIdl(o.namedAt)}; }

namespace {

constexpr CORBA::ULong kNoCrossingIdl = 0xFFFFFFFFu;

CORBA::ULong crossingToIdl(std::size_t crossing) {
  return crossing == kNoCrossing ? kNoCrossingIdl : static_cast<CORBA::ULong>(crossing);
}

std::size_t crossingFromIdl(CORBA::ULong crossing) {
  return crossing == kNoCrossingIdl ? kNoCrossing : std::size_t{crossing};
}

}  // namespace

RGNav::RgGateway toIdl(const GatewayView& g) {
  RGNav::RgGateway out;
  out.id = g.id.value();
  out.detectorId = g.detectorId.value();
  out.classes = toIdl(g.classes);
  out.door = g.door;
  out.neutralised = g.neutralised;
  out.gatewayPoints = toIdl(g.gatewayPoints);
  out.crossingPoints = toIdl(g.crossingPoints);
  out.sideA = g.sideA.value();
  out.sideB = g.sideB.value();
  out.traversals = static_cast<CORBA::ULong>(g.traversals);
  out.sideACrossing = crossingToIdl(g.sideCrossings[kSideA]);
  out.sideBCrossing = crossingToIdl(g.sideCrossings[kSideB]);
  return out;
}

GatewayView fromIdl(const RGNav::RgGateway& g) {
  return {GatewayId(g.id), DetectorGatewayId(g.detectorId), fromIdl(g.classes), static_cast<bool>(g.door),
          static_cast<bool>(g.neutralised), fromIdl(g.gatewayPoints), fromIdl(g.crossingPoints), RegionId(g.sideA),
          RegionId(g.sideB), g.traversals, {crossingFromIdl(g.sideACrossing), crossingFromIdl(g.sideBCrossing)}};
}

RGNav::RgGraphInfo toIdl(const GraphView& graph) {
  RGNav::RgGraphInfo out;
  out.nodes = toIdlSeq<RGNav::RgNodeSeq>(graph.nodes, [](const GraphNodeView& n) { return toIdl(n); });
  out.edges = toIdlSeq<RGNav::RgEdgeSeq>(graph.edges, [](const GraphEdgeView& e) {
    return RGNav::RgEdge{static_cast<CORBA::ULong>(e.from), static_cast<CORBA::ULong>(e.to), e.throughGateway(),
                         e.throughGateway() ? e.gateway.value() : e.region.value(), e.lengthM, e.costM};
  });
  return out;
}

GraphView fromIdl(const RGNav::RgGraphInfo& graph) {
  GraphView out;
  out.nodes = fromIdlSeq<std::vector<GraphNodeView>>(graph.nodes, [](const RGNav::RgNode& n) { return fromIdl(n); });
  out.edges = fromIdlSeq<std::vector<GraphEdgeView>>(graph.edges, [](const RGNav::RgEdge& e) {
    return e.throughGateway ? GraphEdgeView{e.from, e.to, GatewayId(e.through), RegionId{}, e.length, e.cost}
                            : GraphEdgeView{e.from, e.to, GatewayId{}, RegionId(e.through), e.length, e.cost};
  });
  return out;
}

RGNav::RgPath toIdl(const PathView& path) {
  RGNav::RgPath out;
  out.crossings = toIdlSeq<RGNav::RgNodeSeq>(path.crossings, [](const GraphNodeView& n) { return toIdl(n); });
  out.cost = path.costM;
  out.length = path.lengthM;
  return out;
}

PathView fromIdl(const RGNav::RgPath& path) {
  return {fromIdlSeq<std::vector<GraphNodeView>>(path.crossings, [](const RGNav::RgNode& n) { return fromIdl(n); }),
          path.cost, path.length};
}

RGNav::RgMapSummary toIdl(const MapSummaryView& s) {
  return RGNav::RgMapSummary{static_cast<CORBA::ULong>(s.regions), static_cast<CORBA::ULong>(s.gateways),
                             static_cast<CORBA::ULong>(s.neutralised), static_cast<CORBA::ULong>(s.hypotheses), s.lastScan,
                             s.lastEvent, s.current.value(), s.endOfData};
}

MapSummaryView fromIdl(const RGNav::RgMapSummary& s) {
  return {s.regions,   s.gateways,          s.neutralized, s.hypotheses, s.lastScan,
          s.lastEvent, RegionId(s.current), static_cast<bool>(s.endOfData)};
}

RGNav::RgMapEventBatch toIdl(const RgMapEventBatch& b) {
  RGNav::RgMapEventBatch out;
  out.events = toIdlSeq<RGNav::RgMapEventSeq>(b.events, [](const RgMapEvent& e) {
    RGNav::RgMapEvent x;
    x.id = e.id;
    x.kind = std::string(eventKindName(e.kind)).c_str();
    x.region = e.region.value();
    x.other = e.other.value();
    x.gateway = e.gateway.value();
    x.scanId = e.scanId;
    return x;
  });
  out.latestId = b.latestId;
  out.lastScan = b.lastScan;
  out.endOfData = b.endOfData;
  return out;
}

RgMapEventBatch fromIdl(const RGNav::RgMapEventBatch& b) {
  RgMapEventBatch out;
  out.events = fromIdlSeq<std::vector<RgMapEvent>>(b.events, [](const RGNav::RgMapEvent& e) {
    const auto kind = parseEventKind(e.kind.in());
    if (!kind) throw FormatError("RGMappingKernel::eventsSince", 0, std::string("unknown event kind ") + e.kind.in());
    return RgMapEvent{e.id, *kind, RegionId(e.region), RegionId(e.other), GatewayId(e.gateway), e.scanId};
  });
  out.latestId = b.latestId;
  out.lastScan = b.lastScan;
  out.endOfData = b.endOfData;
  return out;
}

}  // namespace rgnav
