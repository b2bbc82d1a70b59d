// JSON checkpoints of the GatewayDetection module; see DetectionStateCodec.h.
#include "core/gateways/detection/DetectionStateCodec.h"

#include <nlohmann/json.hpp>

#include "core/common/Errors.h"
#include "core/common/JsonForms.h"
#include "core/gateways/detection/GatewayRecordJson.h"

namespace rgnav {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "rgnav-gateway-detection";
constexpr int kVersion = 3;

template <class T, class F>
json list(const std::vector<T>& items, F&& write) {
  json out = json::array();
  for (const T& item : items) out.push_back(write(item));
  return out;
}

template <class T, class F>
std::vector<T> list(const json& j, F&& read) {
  std::vector<T> out;
  for (const json& item : j) out.push_back(read(item));
  return out;
}

json gatewayPoints(const GatewayPoints& p) { return jsonPoints(std::vector<Eigen::Vector2d>(p.begin(), p.end())); }
GatewayPoints gatewayPoints(const json& j) {
  const std::vector<Eigen::Vector2d> v = pointsFrom(j);
  if (v.size() != 4) throw std::out_of_range("gateway points: want 4");
  return {v[0], v[1], v[2], v[3]};
}

json trackedGateway(const TrackedGateway& g) {
  return {{"id", g.id}, {"left", jsonPoint(g.left)}, {"right", jsonPoint(g.right)}, {"confidence", g.meanConfidence},
          {"support", g.support}, {"observations", g.observations}, {"first", g.firstScan}, {"last", g.lastScan},
          {"lastPose", jsonPose(g.lastRobotPose)}, {"confirmed", g.confirmed}, {"superseded", g.superseded},
          {"traversals", g.traversals}};
}
TrackedGateway trackedGateway(const json& j) {
  TrackedGateway g;
  g.id = integerFrom(j.at("id"));
  g.left = pointFrom(j.at("left"));
  g.right = pointFrom(j.at("right"));
  g.meanConfidence = j.at("confidence");
  g.support = integerFrom(j.at("support"));
  g.observations = integerFrom(j.at("observations"));
  g.firstScan = integerFrom(j.at("first"));
  g.lastScan = integerFrom(j.at("last"));
  g.lastRobotPose = poseFrom(j.at("lastPose"));
  g.confirmed = j.at("confirmed");
  g.superseded = j.value("superseded", false);  // version 2 had no superseded track
  g.traversals = integerFrom(j.at("traversals"));
  return g;
}

json passages(const PassageTrackerState& s) {
  json tracks = list(s.tracks, [](const PassageTrackState& t) {
    return json{{"gateway", trackedGateway(t.gateway)}, {"leftSum", jsonPoint(t.leftSum)}, {"rightSum", jsonPoint(t.rightSum)},
                {"confidenceSum", t.confidenceSum}, {"lastUpdate", t.lastUpdate}};
  });
  return {{"tracks", tracks}, {"updates", s.updates}, {"nextId", s.nextId},
          {"lastPose", s.lastPose ? jsonPose(*s.lastPose) : json()}};
}
PassageTrackerState passages(const json& j) {
  PassageTrackerState s;
  s.tracks = list<PassageTrackState>(j.at("tracks"), [](const json& t) {
    return PassageTrackState{trackedGateway(t.at("gateway")), pointFrom(t.at("leftSum")), pointFrom(t.at("rightSum")),
                             t.at("confidenceSum").get<double>(), integerFrom(t.at("lastUpdate"))};
  });
  s.updates = integerFrom(j.at("updates"));
  s.nextId = integerFrom(j.at("nextId"));
  if (!j.at("lastPose").is_null()) s.lastPose = poseFrom(j.at("lastPose"));
  return s;
}

json sequence(const TrackedSequence& s) {
  return {{"id", s.id}, {"points", gatewayPoints(s.gatewayPoints)}, {"distances", s.distances},
          {"observations", s.observations}, {"end", static_cast<int>(s.end)}};
}
TrackedSequence sequence(const json& j) {
  TrackedSequence s;
  s.id = integerFrom(j.at("id"));
  s.gatewayPoints = gatewayPoints(j.at("points"));
  s.distances = j.at("distances").get<std::vector<double>>();
  s.observations = j.at("observations").get<std::vector<std::vector<double>>>();
  const int end = integerFrom(j.at("end"));
  if (end < 0 || end > static_cast<int>(SequenceEnd::Flushed)) throw std::out_of_range("sequence end");
  s.end = static_cast<SequenceEnd>(end);
  return s;
}

json sequences(const HypothesisTrackerState& s) {
  return {{"nextId", s.nextId},
          {"running", list(s.running,
                           [](const RunningSequence& r) {
                             return json{{"sequence", sequence(r.sequence)}, {"missed", r.missed}, {"coasted", r.coasted}};
                           })},
          {"finished", list(s.finished, [](const TrackedSequence& f) { return sequence(f); })}};
}
HypothesisTrackerState sequences(const json& j) {
  HypothesisTrackerState s;
  s.nextId = integerFrom(j.at("nextId"));
  s.running = list<RunningSequence>(j.at("running"), [](const json& r) {
    return RunningSequence{sequence(r.at("sequence")), integerFrom(r.at("missed")),
                           integerFrom(r.at("coasted"))};
  });
  s.finished = list<TrackedSequence>(j.at("finished"), [](const json& f) { return sequence(f); });
  return s;
}

json areas(const HallwayAreaState& s) {
  json all = list(s.areas, [](const HallwayArea& a) {
    json views = list(a.views, [](const HallwayView& v) {
      return json{{"entrance", jsonPoint(v.entrance)},
                  {"posterior", std::vector<double>(v.posterior.data(), v.posterior.data() + v.posterior.size())},
                  {"sequences", v.sequences}};
    });
    return json{{"points", gatewayPoints(a.points)}, {"views", views}, {"first", a.firstScan}, {"last", a.lastScan},
                {"lastPose", jsonPose(a.lastRobotPose)}, {"traversals", a.traversals},
                {"enteredThrough", a.enteredThrough ? json(*a.enteredThrough) : json()}};
  });
  return {{"areas", all}, {"lastPosition", s.lastPosition ? jsonPoint(*s.lastPosition) : json()}};
}
HallwayAreaState areas(const json& j) {
  HallwayAreaState s;
  s.areas = list<HallwayArea>(j.at("areas"), [](const json& a) {
    HallwayArea area;
    area.points = gatewayPoints(a.at("points"));
    area.views = list<HallwayView>(a.at("views"), [](const json& v) {
      const std::vector<double> p = v.at("posterior").get<std::vector<double>>();
      return HallwayView{pointFrom(v.at("entrance")), Eigen::Map<const Eigen::VectorXd>(p.data(), static_cast<Eigen::Index>(p.size())),
                         integerFrom(v.at("sequences"))};
    });
    area.firstScan = integerFrom(a.at("first"));
    area.lastScan = integerFrom(a.at("last"));
    area.lastRobotPose = poseFrom(a.at("lastPose"));
    area.traversals = integerFrom(a.at("traversals"));
    if (!a.at("enteredThrough").is_null()) area.enteredThrough = static_cast<std::size_t>(integerFrom(a.at("enteredThrough")));
    return area;
  });
  if (!j.at("lastPosition").is_null()) s.lastPosition = pointFrom(j.at("lastPosition"));
  return s;
}

json event(const GatewayEvent& e) {
  const TraversalReport& t = e.traversal;
  return {{"id", e.id}, {"kind", static_cast<int>(e.kind)}, {"scan", e.scanId}, {"gateway", jsonGatewayRecord(e.gateway)},
          {"traversal", {{"scan", t.scanId}, {"from", t.fromSide}, {"to", t.toSide}, {"at", jsonPoint(t.at)},
                         {"direction", jsonPoint(t.direction)}}}};
}
GatewayEvent event(const json& j) {
  GatewayEvent e;
  e.id = integerFrom(j.at("id"));
  const int kind = integerFrom(j.at("kind"));
  if (kind < 0 || kind > static_cast<int>(GatewayEventKind::Traversed)) throw std::out_of_range("event kind");
  e.kind = static_cast<GatewayEventKind>(kind);
  e.scanId = integerFrom(j.at("scan"));
  e.gateway = gatewayRecordFrom(j.at("gateway"));
  const json& t = j.at("traversal");
  e.traversal = {integerFrom(t.at("scan")), integerFrom(t.at("from")), integerFrom(t.at("to")), pointFrom(t.at("at")), pointFrom(t.at("direction"))};
  return e;
}

template <class K>
json idMap(const std::map<K, DetectorGatewayId>& m) {
  json out = json::array();
  for (const auto& [k, v] : m) out.push_back(json::array({k, v}));
  return out;
}
template <class K>
std::map<K, DetectorGatewayId> idMap(const json& j) {
  std::map<K, DetectorGatewayId> out;
  for (const json& pair : j) out.emplace(static_cast<K>(integerFrom(pair.at(0))), static_cast<DetectorGatewayId>(integerFrom(pair.at(1))));
  return out;
}

}  // namespace

std::string serializeDetection(const DetectionCheckpoint& c) {
  const GatewayDetectorState& d = c.detector;
  const json j = {{"format", kFormat},
                  {"version", kVersion},
                  {"passages", passages(d.passages)},
                  {"sequences", sequences(d.sequences)},
                  {"areas", areas(d.areas)},
                  {"passageIds", idMap(d.passageIds)},
                  {"areaIds", idMap(d.areaIds)},
                  {"nextGatewayId", d.nextGatewayId},
                  {"nextEventId", d.nextEventId},
                  {"lastScan", d.lastScan},
                  {"events", list(c.events, [](const GatewayEvent& e) { return event(e); })}};
  return j.dump();
}

DetectionCheckpoint deserializeDetection(const std::string& text) {
  try {
    const json j = json::parse(text);
    if (j.at("format") != kFormat) throw FormatError("<checkpoint>", 0, "not a gateway detection checkpoint");
    if (j.at("version") != kVersion && j.at("version") != kVersion - 1)
      throw FormatError("<checkpoint>", 0, "version " + j.at("version").dump() + ", this program reads " +
                                               std::to_string(kVersion - 1) + " and " + std::to_string(kVersion));
    DetectionCheckpoint c;
    GatewayDetectorState& d = c.detector;
    d.passages = passages(j.at("passages"));
    d.sequences = sequences(j.at("sequences"));
    d.areas = areas(j.at("areas"));
    d.passageIds = idMap<PassageTrackId>(j.at("passageIds"));
    d.areaIds = idMap<std::size_t>(j.at("areaIds"));
    d.nextGatewayId = integerFrom(j.at("nextGatewayId"));
    d.nextEventId = integerFrom(j.at("nextEventId"));
    d.lastScan = integerFrom(j.at("lastScan"));
    c.events = list<GatewayEvent>(j.at("events"), [](const json& e) { return event(e); });
    return c;
  } catch (const json::exception& e) {
    throw FormatError("<checkpoint>", 0, e.what());
  } catch (const std::out_of_range& e) {
    throw FormatError("<checkpoint>", 0, e.what());
  }
}

}  // namespace rgnav
