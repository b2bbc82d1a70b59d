// JSON checkpoints of the RG Mapping Kernel; see RgMapCodec.h.
#include "core/rgmap/kernel/RgMapCodec.h"

#include <charconv>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "core/common/Errors.h"
#include "core/common/JsonForms.h"
#include "core/gateways/detection/GatewayRecordJson.h"
#include "core/rgmap/kernel/RgMapConsistency.h"
#include "core/rgmap/kernel/RgMapGraph.h"

namespace rgnav {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "rgnav-rg-map";
constexpr int kVersion = 4;

[[noreturn]] void damaged(const std::string& what) { throw FormatError("<checkpoint>", 0, what); }

// A finite float as the double of its shortest decimal form, when that reads back to the float.
json range(float v) {
  if (!std::isfinite(v)) return jsonNumber(v);
  char text[32];
  const auto written = std::to_chars(text, text + sizeof text, v);
  double shortest = 0.0;
  std::from_chars(text, written.ptr, shortest);
  return static_cast<float>(shortest) == v ? shortest : static_cast<double>(v);
}

template <class T, class F>
json list(const T& items, F&& write) {
  json out = json::array();
  for (const auto& item : items) out.push_back(write(item));
  return out;
}

json gateway(const Gateway& g) {
  const json sides = list(g.sides, [](const GatewaySideRef& s) {
    return json{{"region", s.region},
                {"crossing", s.crossing == kNoCrossing ? json() : json(s.crossing)},
                {"attachedAt", s.attachedAt}};
  });
  return {{"id", g.id},
          {"record", jsonGatewayRecord(g.record)},
          {"aliases", g.aliases},
          {"odomToMap", jsonPose(g.odomToMap)},
          {"sides", sides},
          {"traversalsFrom", g.traversalsFrom},
          {"neutralised", g.neutralised}};
}
Gateway gateway(const json& j) {
  Gateway g;
  g.id = integerFrom(j.at("id"));
  g.record = gatewayRecordFrom(j.at("record"));
  g.aliases = integersFrom<std::vector<DetectorGatewayId>>(j.at("aliases"));
  g.odomToMap = poseFrom(j.at("odomToMap"));
  const json& sides = j.at("sides");
  if (sides.size() != 2) damaged("gateway " + std::to_string(g.id.value()) + ": want two sides");
  for (std::size_t i = 0; i < 2; ++i) {
    const json& s = sides.at(i);
    g.sides[i] = {static_cast<RegionId>(integerFrom(s.at("region"))),
                  s.at("crossing").is_null() ? kNoCrossing : static_cast<std::size_t>(integerFrom(s.at("crossing"))),
                  static_cast<DataId>(integerFrom(s.at("attachedAt")))};
  }
  g.traversalsFrom = integersFrom<std::array<std::size_t, 2>>(j.at("traversalsFrom"));
  g.neutralised = j.at("neutralised").get<bool>();
  return g;
}

json region(const Region& r) {
  json names = json::object();
  for (const auto& [name, at] : r.objectNames) names[name] = {jsonNumber(at.x()), jsonNumber(at.y())};
  return {{"id", r.id},     {"frame", jsonPose(r.frame)},  {"scans", r.scans}, {"gateways", r.gateways},
          {"name", r.name}, {"finalised", r.finalised}, {"objectNames", names}};
}
// "objectNames" came with object naming; a checkpoint written before has none.
Region region(const json& j) {
  Region r{static_cast<RegionId>(integerFrom(j.at("id"))),
           poseFrom(j.at("frame")),
           integersFrom<std::vector<DataId>>(j.at("scans")),
           integersFrom<std::set<GatewayId>>(j.at("gateways")),
           j.at("name").get<std::string>(),
           j.at("finalised").get<bool>(),
           {}};
  if (j.contains("objectNames"))
    for (const auto& [name, at] : j.at("objectNames").items())
      r.objectNames[name] = {at.at(0).get<double>(), at.at(1).get<double>()};
  return r;
}

json revertibleMerge(const RevertibleMerge& m) {
  json sides = json::array();
  for (const auto& [g, regions] : m.sides) sides.push_back(json::array({g, regions[kSideA], regions[kSideB]}));
  return {{"kept", region(m.kept)},       {"absorbed", region(m.absorbed)},
          {"sides", sides},               {"current", m.current},
          {"visitStart", m.visitStart},   {"lastScan", m.lastScan}};
}
RevertibleMerge revertibleMerge(const json& j) {
  RevertibleMerge m{region(j.at("kept")),
                    region(j.at("absorbed")),
                    {},
                    static_cast<RegionId>(integerFrom(j.at("current"))),
                    static_cast<DataId>(integerFrom(j.at("visitStart"))),
                    static_cast<DataId>(integerFrom(j.at("lastScan")))};
  for (const json& g : j.at("sides"))
    m.sides[static_cast<GatewayId>(integerFrom(g.at(0)))] = {static_cast<RegionId>(integerFrom(g.at(1))),
                                                             static_cast<RegionId>(integerFrom(g.at(2)))};
  return m;
}

json laser(const LaserScan& l) {
  return {{"id", l.id},
          {"stamp", jsonNumber(l.stamp)},
          {"odometry", jsonPose(l.odometry)},
          {"sensorPose", jsonPose(l.sensorPose)},
          {"startAngle", jsonNumber(l.startAngle)},
          {"increment", jsonNumber(l.angleIncrement)},
          {"maxRange", jsonNumber(l.maxRange)},
          {"ranges", list(l.ranges, [](float r) { return range(r); })}};
}
LaserScan laser(const json& j) {
  LaserScan l;
  l.id = static_cast<DataId>(integerFrom(j.at("id")));
  l.stamp = numberFrom(j.at("stamp"));
  l.odometry = poseFrom(j.at("odometry"));
  l.sensorPose = poseFrom(j.at("sensorPose"));
  l.startAngle = numberFrom(j.at("startAngle"));
  l.angleIncrement = numberFrom(j.at("increment"));
  l.maxRange = numberFrom(j.at("maxRange"));
  for (const json& r : j.at("ranges")) l.ranges.push_back(static_cast<float>(numberFrom(r)));
  return l;
}

// The complete lines of a scan journal (a part of a line after the last newline is what a crash
// left of an append) by scan ID; of two lines for one ID the later one.
std::map<DataId, LaserScan> journalScans(const std::string& journal) {
  std::map<DataId, LaserScan> scans;
  std::size_t begin = 0;
  for (std::size_t end = journal.find('\n'); end != std::string::npos; begin = end + 1, end = journal.find('\n', begin)) {
    if (end == begin) continue;
    LaserScan l = laser(json::parse(journal.begin() + static_cast<std::ptrdiff_t>(begin),
                                    journal.begin() + static_cast<std::ptrdiff_t>(end)));
    const DataId id = l.id;
    scans.insert_or_assign(id, std::move(l));
  }
  return scans;
}

json event(const RgMapEvent& e) {
  return {{"id", e.id},       {"kind", eventKindName(e.kind)}, {"region", e.region},
          {"other", e.other}, {"gateway", e.gateway},          {"scan", e.scanId}};
}
RgMapEvent event(const json& j) {
  const std::string name = j.at("kind");
  const std::optional<RgMapEventKind> kind = parseEventKind(name);
  if (!kind) damaged("event kind " + name);
  return {static_cast<RgMapEventId>(integerFrom(j.at("id"))),   *kind,
          static_cast<RegionId>(integerFrom(j.at("region"))),   static_cast<RegionId>(integerFrom(j.at("other"))),
          static_cast<GatewayId>(integerFrom(j.at("gateway"))), static_cast<DataId>(integerFrom(j.at("scan")))};
}

json node(const NodeKey& k) { return json::array({k.gateway, k.side == GatewaySide::A ? "A" : "B"}); }
NodeKey node(const json& j) {
  const std::string side = j.at(1);
  if (side != "A" && side != "B") damaged("gateway side " + side);
  return {static_cast<GatewayId>(integerFrom(j.at(0))), side == "A" ? GatewaySide::A : GatewaySide::B};
}

json costs(const RgMapState& s) {
  json traversals = json::array();
  for (const auto& [edge, stats] : s.edgeTraversals)
    traversals.push_back({{"kind", edge.kind == EdgeKind::Gateway ? "gateway" : "region"},
                          {"a", node(edge.a)},
                          {"b", node(edge.b)},
                          {"mean", jsonNumber(stats.meanM)},
                          {"count", stats.count}});
  json doors = json::array();
  for (const auto& [g, offset] : s.doorOffsets) doors.push_back(json::array({g, jsonNumber(offset)}));
  return {{"traversals", traversals}, {"doorOffsets", doors}};
}
void costs(const json& j, RgMapState& s) {
  for (const json& t : j.at("traversals")) {
    const std::string kind = t.at("kind");
    if (kind != "gateway" && kind != "region") damaged("edge kind " + kind);
    const EdgeKey key =
        edgeKey(kind == "gateway" ? EdgeKind::Gateway : EdgeKind::Region, node(t.at("a")), node(t.at("b")));
    s.edgeTraversals[key] = {numberFrom(t.at("mean")), static_cast<std::size_t>(integerFrom(t.at("count")))};
  }
  for (const json& d : j.at("doorOffsets")) s.doorOffsets[static_cast<GatewayId>(integerFrom(d.at(0)))] = numberFrom(d.at(1));
}

// Reads the items of `j` into `into`, keyed by key(item); a key seen twice is damage.
template <class Map, class Read, class Key>
void insertAll(const json& j, Map& into, Read&& read, Key&& key, const char* what) {
  for (const json& item : j) {
    auto value = read(item);
    const auto k = key(value);
    if (!into.emplace(k, std::move(value)).second) damaged(std::string("duplicate ") + what + " " + json(k).dump());
  }
}

}  // namespace

std::string serializeRgMap(const RgMapState& s) {
  const json j = {{"format", kFormat},
                  {"version", kVersion},
                  {"current", s.current},
                  {"visitStart", s.visitStart},
                  {"nextRegionId", s.nextRegionId},
                  {"nextGatewayId", s.nextGatewayId},
                  {"lastScanId", s.lastScanId},
                  {"lastGatewayEventId", s.lastGatewayEventId},
                  {"lastPoseRevision", s.lastPoseRevision},
                  {"regions", list(s.regions, [](const auto& r) { return region(r.second); })},
                  {"gateways", list(s.gateways, [](const auto& g) { return gateway(g.second); })},
                  {"scans", list(s.scans, [](const auto& sc) {
                     return json{{"id", sc.first}, {"corrected", jsonPose(sc.second.corrected)}};
                   })},
                  {"events", list(s.events, [](const RgMapEvent& e) { return event(e); })},
                  {"costs", costs(s)},
                  {"revertibleMerges", list(s.revertibleMerges, [](const RevertibleMerge& m) { return revertibleMerge(m); })}};
  return j.dump();
}

std::string scanJournalLines(const RgMapState& state, DataId afterId) {
  std::string lines;
  for (auto s = state.scans.upper_bound(afterId); s != state.scans.end(); ++s) lines += laser(s->second.scan).dump() + "\n";
  return lines;
}

RgMapState deserializeRgMap(const std::string& text, const std::string& journal) {
  RgMapState s;
  try {
    std::map<DataId, LaserScan> lasers = journalScans(journal);
    const json j = json::parse(text);
    if (j.at("format") != kFormat) damaged("not an RG map checkpoint");
    if (j.at("version") != kVersion)
      damaged("version " + j.at("version").dump() + ", this program reads " + std::to_string(kVersion));
    s.current = integerFrom(j.at("current"));
    s.visitStart = integerFrom(j.at("visitStart"));
    s.nextRegionId = integerFrom(j.at("nextRegionId"));
    s.nextGatewayId = integerFrom(j.at("nextGatewayId"));
    s.lastScanId = integerFrom(j.at("lastScanId"));
    s.lastGatewayEventId = integerFrom(j.at("lastGatewayEventId"));
    s.lastPoseRevision = integerFrom(j.at("lastPoseRevision"));
    insertAll(
        j.at("regions"), s.regions, [](const json& r) { return region(r); }, [](const Region& r) { return r.id; },
        "region");
    insertAll(
        j.at("gateways"), s.gateways, [](const json& g) { return gateway(g); }, [](const Gateway& g) { return g.id; },
        "gateway");
    insertAll(
        j.at("scans"), s.scans,
        [&](const json& sc) {
          const DataId id = static_cast<DataId>(integerFrom(sc.at("id")));
          const auto found = lasers.find(id);
          if (found == lasers.end()) damaged("scan " + std::to_string(id) + " is not in the scan journal");
          return StoredScan{std::move(found->second), poseFrom(sc.at("corrected"))};
        },
        [](const StoredScan& sc) { return sc.scan.id; }, "scan");
    for (const json& e : j.at("events")) s.events.push_back(event(e));
    costs(j.at("costs"), s);
    // "revertibleMerges" came with undoing merges; a checkpoint written before has none.
    if (j.contains("revertibleMerges"))
      for (const json& m : j.at("revertibleMerges")) s.revertibleMerges.push_back(revertibleMerge(m));
  } catch (const json::exception& e) {
    damaged(e.what());
  }
  const std::vector<std::string> violations = checkConsistency(s);
  if (!violations.empty()) damaged("inconsistent RG map: " + violations.front());
  try {
    costTable(s, {});
  } catch (const InvalidArgumentError& e) {
    damaged(e.what());
  }
  return s;
}

}  // namespace rgnav
