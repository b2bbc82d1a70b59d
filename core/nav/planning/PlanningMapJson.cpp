// An exported RG map read into a PlanningMap (see PlanningMapJson.h).
#include "core/nav/planning/PlanningMapJson.h"

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/JsonForms.h"
#include "core/rgmap/export/Base64.h"

namespace rgnav {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "rgnav-rgmap";
constexpr int kVersion = 2;

RegionId optionalRegion(const json& j) { return j.is_null() ? RegionId{} : RegionId(integerFrom(j)); }

RegionView region(const json& j) {
  RegionView r;
  r.summary.id = integerFrom(j.at("id"));
  r.summary.name = j.at("name").get<std::string>();
  const json& frame = j.at("frame");
  r.summary.frame = {numberFrom(frame.at("x")), numberFrom(frame.at("y")), numberFrom(frame.at("theta"))};
  r.summary.scans = integerFrom(j.at("scanCount"));
  r.summary.finalised = j.at("finalised").get<bool>();
  for (const json& g : j.at("gateways")) r.summary.gateways.push_back(integerFrom(g));
  for (const json& l : j.at("lines")) {
    if (!l.is_array() || l.size() != 4) throw FormatError("<map>", 0, "a line is not [x1, y1, x2, y2]: " + l.dump());
    r.lines.push_back({{numberFrom(l[0]), numberFrom(l[1])}, {numberFrom(l[2]), numberFrom(l[3])}});
  }
  if (const json& box = j.at("boundingBox"); !box.is_null()) {
    r.boxMin = pointFrom(box.at("min"));
    r.boxMax = pointFrom(box.at("max"));
  }
  const json& f = j.at("freespace");
  r.freespace.resolutionM = numberFrom(f.at("resolution"));
  r.freespace.originM = pointFrom(f.at("origin"));
  r.freespace.width = integerFrom(f.at("width"));
  r.freespace.height = integerFrom(f.at("height"));
  r.freespace.bytes = decodeBase64(f.at("bits").get<std::string>());
  if (r.freespace.width < 0 || r.freespace.height < 0 || !(r.freespace.resolutionM > 0.0))
    throw FormatError("<map>", 0, "region " + std::to_string(r.summary.id.value()) + ": a freespace of " +
                                      f.at("width").dump() + " x " + f.at("height").dump() + " cells of " +
                                      f.at("resolution").dump() + " m");
  const std::size_t cells = std::size_t(r.freespace.width) * std::size_t(r.freespace.height);
  if (r.freespace.bytes.size() != (cells + 7) / 8)
    throw FormatError("<map>", 0, "region " + std::to_string(r.summary.id.value()) + ": " +
                                      std::to_string(r.freespace.bytes.size()) + " freespace bytes for " +
                                      std::to_string(cells) + " cells");
  r.areaM2 = numberFrom(j.at("area"));
  r.centroid = pointFrom(j.at("centroid"));
  const json& axes = j.at("mainAxes");
  r.majorAxisAngleRad = numberFrom(axes.at("angle"));
  r.majorVariance = numberFrom(axes.at("majorVariance"));
  r.minorVariance = numberFrom(axes.at("minorVariance"));
  for (const json& d : j.at("mainDirections"))
    r.mainDirections.push_back({numberFrom(d.at("angle")), numberFrom(d.at("length")), numberFrom(d.at("share"))});
  r.accuracyInlierShare = numberFrom(j.at("accuracy").at("inlierShare"));
  r.accuracyRmsM = numberFrom(j.at("accuracy").at("rmsDistance"));
  r.completeness = numberFrom(j.at("completeness").at("value"));
  for (const json& o : j.value("objects", json::array())) {
    const Eigen::Vector2d centre = pointFrom(o.at("center"));
    r.objects.push_back({{centre.x(), centre.y(), numberFrom(o.at("angle"))}, numberFrom(o.at("length")),
                         numberFrom(o.at("width")), numberFrom(o.at("confidence")), o.at("name").get<std::string>()});
  }
  return r;
}

GatewayView gateway(const json& j) {
  GatewayView g;
  g.id = integerFrom(j.at("id"));
  g.detectorId = integerFrom(j.at("detectorId"));
  for (const json& c : j.at("classes")) g.classes.push_back({c.at("name").get<std::string>(), numberFrom(c.at("p"))});
  g.door = j.at("door").get<bool>();
  g.neutralised = j.at("neutralised").get<bool>();
  g.gatewayPoints = pointsFrom(j.at("gatewayPoints"));
  g.crossingPoints = pointsFrom(j.at("crossingPoints"));
  const json& sides = j.at("sides");
  if (!sides.is_array() || sides.size() != 2) throw FormatError("<map>", 0, "a gateway has not 2 sides: " + sides.dump());
  g.sideA = optionalRegion(sides[0].at("region"));
  g.sideB = optionalRegion(sides[1].at("region"));
  g.traversals = integerFrom(j.at("traversals"));
  return g;
}

GraphView graph(const json& j) {
  GraphView out;
  std::map<std::string, std::size_t> index;
  for (const json& n : j.at("nodes")) {
    const std::string side = n.at("side").get<std::string>();
    if (side != "A" && side != "B") throw FormatError("<map>", 0, "a node's side is not A or B: " + n.dump());
    index[n.at("key").get<std::string>()] = out.nodes.size();
    out.nodes.push_back({integerFrom(n.at("gateway")), side == "A" ? 0u : 1u, integerFrom(n.at("region")),
                         pointFrom(n.at("position"))});
  }
  const auto node = [&](const json& key) {
    const auto found = index.find(key.get<std::string>());
    if (found == index.end()) throw FormatError("<map>", 0, "an edge names the unknown node " + key.dump());
    return found->second;
  };
  for (const json& e : j.at("edges")) {
    const std::string kind = e.at("kind").get<std::string>();
    if (kind != "gateway" && kind != "region") throw FormatError("<map>", 0, "unknown edge kind " + kind);
    GraphEdgeView edge;
    edge.from = node(e.at("from"));
    edge.to = node(e.at("to"));
    if (kind == "gateway") edge.gateway = integerFrom(e.at("through"));
    else edge.region = integerFrom(e.at("through"));
    edge.lengthM = numberFrom(e.at("length"));
    edge.costM = numberFrom(e.at("cost"));
    out.edges.push_back(edge);
  }
  return out;
}

}  // namespace

PlanningMap planningMapFromJson(const std::string& text, const std::string& source) {
  return readingJson(source, [&] {
    const json j = json::parse(text);
    if (j.at("format") != kFormat || j.at("version") != kVersion)
      throw FormatError(source, 0, std::string("not a ") + kFormat + " version " + std::to_string(kVersion) + " map");
    PlanningMap map;
    for (const json& r : j.at("regions")) map.regions.push_back(region(r));
    // The detector's gateways no region has taken in yet too: the PathPlanning module plans with
    // them (gatewayViews), so an offline plan on the exported map must as well.
    for (const json& g : j.at("gateways")) map.gateways.push_back(gateway(g));
    for (const json& g : j.at("gatewayHypotheses")) map.gateways.push_back(gateway(g));
    map.graph = graph(j.at("graph"));
    map.revision = integerFrom(j.at("summary").at("lastEventId"));
    return map;
  });
}

PlanningMap loadPlanningMap(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw FileError(file + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw FileError(file + ": cannot be read");
  return planningMapFromJson(text.str(), file);
}

}  // namespace rgnav
