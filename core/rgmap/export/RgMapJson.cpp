// The RG Map's JSON export; see RgMapJson.h and RGMAP_JSON.md.
#include "core/rgmap/export/RgMapJson.h"

#include <nlohmann/json.hpp>

#include "core/common/AtomicFile.h"
#include "core/common/JsonForms.h"
#include "core/rgmap/export/Base64.h"
#include "core/rgmap/export/ExportNumbers.h"
#include "core/rgmap/export/MapStorage.h"
#include "core/rgmap/kernel/ObjectNames.h"

namespace rgnav {
namespace {

using Json = nlohmann::ordered_json;

constexpr double kGridResolutionM = 0.05;
constexpr const char* kBitOrder = "row-major, bottom row first, least significant bit first";

double length(double v) { return roundDecimals(v, kLengthDecimals); }
double angle(double v) { return roundDecimals(v, kAngleDecimals); }
double ratio(double v) { return roundDecimals(v, kRatioDecimals); }

Json point(const Eigen::Vector2d& p) { return Json::array({length(p.x()), length(p.y())}); }

Json points(const std::vector<Eigen::Vector2d>& ps) {
  Json out = Json::array();
  for (const Eigen::Vector2d& p : ps) out.push_back(point(p));
  return out;
}

// An ID, or null for 0 ("none").
Json optionalId(RegionId id) { return id.isNone() ? Json(nullptr) : Json(id); }

Json freespace(const FreespaceBitmap& f) {
  return {{"resolution", length(f.resolutionM)},
          {"origin", point(f.originM)},
          {"width", f.width},
          {"height", f.height},
          {"bitOrder", kBitOrder},
          {"bits", encodeBase64(f.bytes)}};
}

Json region(const RegionSnapshot& r) {
  const RegionDescription& d = r.description;
  Json lines = Json::array();
  for (const LineSegment& s : r.lines)
    lines.push_back({length(s.start.x()), length(s.start.y()), length(s.end.x()), length(s.end.y())});
  Json directions = Json::array();
  for (const MainDirection& m : d.mainDirections)
    directions.push_back({{"angle", angle(m.angleRad)}, {"length", length(m.lengthM)}, {"share", ratio(m.share)}});
  Json objects = Json::array();
  const std::vector<std::string> names = objectNamesOf(r.region, d.objects);
  for (std::size_t i = 0; i < d.objects.size(); ++i) {
    const Rectangle2D& o = d.objects[i];
    objects.push_back({{"kind", "rectangle"},
                       {"center", point({o.pose.x, o.pose.y})},
                       {"angle", angle(o.pose.theta)},
                       {"length", length(o.lengthM)},
                       {"width", length(o.widthM)},
                       {"confidence", ratio(o.confidence)},
                       {"name", names[i]}});
  }
  const Json box = d.boundingBox.isEmpty()
                       ? Json(nullptr)
                       : Json{{"min", point(d.boundingBox.min())}, {"max", point(d.boundingBox.max())}};
  const Json minimumBox = !d.minimumAreaBox ? Json(nullptr)
                                            : Json{{"center", point(d.minimumAreaBox->center)},
                                                   {"angle", angle(d.minimumAreaBox->angleRad)},
                                                   {"length", length(d.minimumAreaBox->lengthM)},
                                                   {"width", length(d.minimumAreaBox->widthM)}};
  return {{"id", r.region.id},
          {"name", r.region.name},
          {"frame", {{"x", length(r.region.frame.x)}, {"y", length(r.region.frame.y)},
                     {"theta", angle(r.region.frame.theta)}}},
          {"finalised", r.region.finalised},
          {"scanCount", r.region.scans.size()},
          {"gateways", r.region.gateways},
          {"lines", lines},
          {"boundingBox", box},
          {"minimumAreaBox", minimumBox},
          {"freespace", freespace(d.freespace)},
          {"area", length(d.moments.areaM2)},
          {"centroid", point(d.moments.centroid)},
          {"centroidInBox", {ratio(d.centroidInBox.x()), ratio(d.centroidInBox.y())}},
          {"mainAxes", {{"angle", angle(d.moments.majorAxisAngleRad)},
                        {"majorVariance", length(d.moments.majorVariance)},
                        {"minorVariance", length(d.moments.minorVariance)}}},
          {"mainDirections", directions},
          {"accuracy", {{"points", d.accuracy.pointCount},
                        {"inlierShare", ratio(d.accuracy.inlierShare)},
                        {"meanDistance", length(d.accuracy.meanDistanceM)},
                        {"rmsDistance", length(d.accuracy.rmsDistanceM)}}},
          {"completeness", {{"value", ratio(d.completeness.completeness)},
                            {"frontierShare", ratio(d.completeness.frontierShare)},
                            {"borderCells", d.completeness.borderCells},
                            {"openCells", d.completeness.openCells}}},
          {"objects", objects}};
}

Json gateway(const GatewaySnapshot& s) {
  const Gateway& g = s.gateway;
  Json classes = Json::array();
  for (const ClassProbability& c : g.record.classes) classes.push_back({{"name", c.name}, {"p", ratio(c.probability)}});
  Json sides = Json::array();
  for (const GatewaySideRef& side : g.sides)
    sides.push_back({{"region", optionalId(side.region)},
                     {"crossing", side.crossing == kNoCrossing ? Json(nullptr) : Json(side.crossing)}});
  return {{"id", g.id},
          {"detectorId", g.record.id},
          {"kind", g.record.kind == GatewayKind::NarrowPassage ? "NarrowPassage" : "HallwayArea"},
          {"door", g.door()},
          {"label", g.record.classes.empty() ? std::string() : g.record.label()},
          {"classes", classes},
          {"width", length(g.record.widthM)},
          {"gatewayPoints", points(s.inMap.gatewayPoints)},
          {"crossingPoints", points(s.inMap.crossingPoints)},
          {"sides", sides},
          {"neutralised", g.neutralised},
          {"traversals", s.traversals()},
          {"traversalsFrom", g.traversalsFrom},
          {"firstScan", g.record.firstScan},
          {"lastScan", g.record.lastScan}};
}

Json graph(const RgMapSnapshot& map) {
  Json nodes = Json::array();
  for (const RgNode& n : map.graphNodes)
    nodes.push_back({{"key", toString(n.key)},
                     {"gateway", n.gateway()},
                     {"side", n.key.side == GatewaySide::A ? "A" : "B"},
                     {"region", n.region},
                     {"position", point(n.position)},
                     {"door", n.door}});
  Json edges = Json::array();
  for (const RgEdge& e : map.graphEdges)
    edges.push_back({{"kind", e.kind() == EdgeKind::Gateway ? "gateway" : "region"},
                     {"from", toString(e.key.a)},
                     {"to", toString(e.key.b)},
                     {"through", e.kind() == EdgeKind::Gateway ? Json(e.gateway) : Json(e.region)},
                     {"length", length(e.lengthM)},
                     {"cost", length(e.costM)}});
  return {{"nodes", nodes}, {"edges", edges}};
}

Json summary(const RgMapSnapshot& map) {
  std::size_t neutralised = 0;
  for (const GatewaySnapshot& g : map.gateways) neutralised += g.gateway.neutralised ? 1 : 0;
  const MapStorage storage = mapStorage(map, kGridResolutionM);
  return {{"regions", map.regions.size()},
          {"gateways", map.gateways.size()},
          {"neutralisedGateways", neutralised},
          {"gatewayHypotheses", map.hypotheses.size()},
          {"scans", map.scanCount},
          {"lastScanId", map.lastScanId},
          {"lastEventId", map.lastEventId},
          {"currentRegion", optionalId(map.currentRegion)},
          {"rgMapBytes", storage.rgMapBytes},
          {"occupancyGridBytes", storage.occupancyGridBytes},
          {"occupancyGridResolution", kGridResolutionM}};
}

}  // namespace

std::string exportRgMapJson(const RgMapSnapshot& map) {
  Json regions = Json::array(), gateways = Json::array(), hypotheses = Json::array();
  for (const RegionSnapshot& r : map.regions) regions.push_back(region(r));
  for (const GatewaySnapshot& g : map.gateways) gateways.push_back(gateway(g));
  for (const GatewaySnapshot& g : map.hypotheses) hypotheses.push_back(gateway(g));
  const Json root = {{"format", kRgMapJsonFormat},
                     {"version", kRgMapJsonVersion},
                     {"summary", summary(map)},
                     {"regions", regions},
                     {"gateways", gateways},
                     {"gatewayHypotheses", hypotheses},
                     {"graph", graph(map)}};
  return root.dump() + "\n";
}

void writeRgMapJson(const std::string& path, const RgMapSnapshot& map) {
  writeFileAtomically(path, exportRgMapJson(map));
}

}  // namespace rgnav
