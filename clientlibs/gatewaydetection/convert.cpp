// Conversions between GatewayDetection.idl types and their plain C++ forms (see convert.h).
#include "clientlibs/gatewaydetection/convert.h"

#include "clientlibs/common/convert.h"

namespace rgnav {
namespace {

RGNav::GatewayKind toIdl(GatewayKind kind) {
  return kind == GatewayKind::NarrowPassage ? RGNav::NARROW_PASSAGE : RGNav::HALLWAY_AREA;
}
GatewayKind fromIdl(RGNav::GatewayKind kind) {
  return kind == RGNav::NARROW_PASSAGE ? GatewayKind::NarrowPassage : GatewayKind::HallwayArea;
}

RGNav::GatewayEventKind toIdl(GatewayEventKind kind) {
  switch (kind) {
    case GatewayEventKind::Detected: return RGNav::GATEWAY_DETECTED;
    case GatewayEventKind::Updated: return RGNav::GATEWAY_UPDATED;
    case GatewayEventKind::Traversed: break;
  }
  return RGNav::GATEWAY_TRAVERSED;
}
GatewayEventKind fromIdl(RGNav::GatewayEventKind kind) {
  switch (kind) {
    case RGNav::GATEWAY_DETECTED: return GatewayEventKind::Detected;
    case RGNav::GATEWAY_UPDATED: return GatewayEventKind::Updated;
    default: return GatewayEventKind::Traversed;
  }
}

}  // namespace

RGNav::Point2D toIdl(const Eigen::Vector2d& p) { return RGNav::Point2D{p.x(), p.y()}; }
Eigen::Vector2d fromIdl(const RGNav::Point2D& p) { return {p.x, p.y}; }

RGNav::Point2DSeq toIdl(const std::vector<Eigen::Vector2d>& points) {
  return toIdlSeq<RGNav::Point2DSeq>(points, [](const Eigen::Vector2d& p) { return toIdl(p); });
}

std::vector<Eigen::Vector2d> fromIdl(const RGNav::Point2DSeq& points) {
  return fromIdlSeq<std::vector<Eigen::Vector2d>>(points, [](const RGNav::Point2D& p) { return fromIdl(p); });
}

RGNav::ClassProbabilitySeq toIdl(const std::vector<ClassProbability>& classes) {
  return toIdlSeq<RGNav::ClassProbabilitySeq>(classes, [](const ClassProbability& c) {
    RGNav::ClassProbability p;
    p.name = c.name.c_str();
    p.probability = c.probability;
    return p;
  });
}

std::vector<ClassProbability> fromIdl(const RGNav::ClassProbabilitySeq& classes) {
  return fromIdlSeq<std::vector<ClassProbability>>(
      classes, [](const RGNav::ClassProbability& c) { return ClassProbability{c.name.in(), c.probability}; });
}

RGNav::GatewayInfo toIdl(const GatewayRecord& g) {
  RGNav::GatewayInfo out;
  out.id = g.id.value();
  out.kind = toIdl(g.kind);
  out.classes = toIdl(g.classes);
  out.gatewayPoints = toIdl(g.gatewayPoints);
  out.crossingPoints = toIdl(g.crossingPoints);
  out.width = g.widthM;
  out.firstScan = g.firstScan;
  out.lastScan = g.lastScan;
  out.lastPose = toIdl(g.lastPose);
  out.support = static_cast<CORBA::ULong>(g.support);
  out.traversals = static_cast<CORBA::ULong>(g.traversals);
  return out;
}

GatewayRecord fromIdl(const RGNav::GatewayInfo& g) {
  GatewayRecord out;
  out.id = DetectorGatewayId(g.id);
  out.kind = fromIdl(g.kind);
  out.classes = fromIdl(g.classes);
  out.gatewayPoints = fromIdl(g.gatewayPoints);
  out.crossingPoints = fromIdl(g.crossingPoints);
  out.widthM = g.width;
  out.firstScan = g.firstScan;
  out.lastScan = g.lastScan;
  out.lastPose = fromIdl(g.lastPose);
  out.support = g.support;
  out.traversals = g.traversals;
  return out;
}

RGNav::GatewayEvent toIdl(const GatewayEvent& e) {
  RGNav::GatewayEvent out;
  out.id = e.id;
  out.kind = toIdl(e.kind);
  out.scanId = e.scanId;
  out.gateway = toIdl(e.gateway);
  out.traversal = RGNav::TraversalInfo{e.traversal.scanId, static_cast<CORBA::ULong>(e.traversal.fromSide),
                                   static_cast<CORBA::ULong>(e.traversal.toSide), toIdl(e.traversal.at),
                                   toIdl(e.traversal.direction)};
  return out;
}

GatewayEvent fromIdl(const RGNav::GatewayEvent& e) {
  GatewayEvent out;
  out.id = e.id;
  out.kind = fromIdl(e.kind);
  out.scanId = e.scanId;
  out.gateway = fromIdl(e.gateway);
  out.traversal = TraversalReport{e.traversal.scanId, e.traversal.fromSide, e.traversal.toSide, fromIdl(e.traversal.at),
                                  fromIdl(e.traversal.direction)};
  return out;
}

RGNav::GatewayEventBatch toIdl(const GatewayEventBatch& b) {
  RGNav::GatewayEventBatch out;
  out.events = toIdlSeq<RGNav::GatewayEventSeq>(b.events, [](const GatewayEvent& e) { return toIdl(e); });
  out.latestId = b.latestId;
  out.lastScan = b.lastScan;
  out.endOfData = b.endOfData;
  return out;
}

GatewayEventBatch fromIdl(const RGNav::GatewayEventBatch& b) {
  return GatewayEventBatch{fromIdlSeq<std::vector<GatewayEvent>>(b.events, [](const RGNav::GatewayEvent& e) { return fromIdl(e); }),
                           b.latestId, b.lastScan, static_cast<bool>(b.endOfData)};
}

}  // namespace rgnav
