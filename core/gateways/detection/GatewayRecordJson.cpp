// GatewayRecord as JSON (see GatewayRecordJson.h).
#include "core/gateways/detection/GatewayRecordJson.h"

#include "core/common/Errors.h"
#include "core/common/JsonForms.h"

namespace rgnav {

using nlohmann::json;

json jsonGatewayRecord(const GatewayRecord& r) {
  json classes = json::array();
  for (const ClassProbability& c : r.classes) classes.push_back({{"name", c.name}, {"p", jsonNumber(c.probability)}});
  return {{"id", r.id},
          {"kind", r.kind == GatewayKind::NarrowPassage ? "NarrowPassage" : "HallwayArea"},
          {"classes", classes},
          {"gatewayPoints", jsonPoints(r.gatewayPoints)},
          {"crossingPoints", jsonPoints(r.crossingPoints)},
          {"width", jsonNumber(r.widthM)},
          {"first", r.firstScan},
          {"last", r.lastScan},
          {"lastPose", jsonPose(r.lastPose)},
          {"support", r.support},
          {"traversals", r.traversals}};
}

GatewayRecord gatewayRecordFrom(const json& j) {
  GatewayRecord r;
  r.id = integerFrom(j.at("id"));
  const std::string kind = j.at("kind");
  if (kind != "NarrowPassage" && kind != "HallwayArea") throw FormatError("<checkpoint>", 0, "gateway kind " + kind);
  r.kind = kind == "NarrowPassage" ? GatewayKind::NarrowPassage : GatewayKind::HallwayArea;
  for (const json& c : j.at("classes")) r.classes.push_back({c.at("name").get<std::string>(), numberFrom(c.at("p"))});
  if (r.classes.empty()) throw FormatError("<checkpoint>", 0, "a gateway without classes");
  r.gatewayPoints = pointsFrom(j.at("gatewayPoints"));
  r.crossingPoints = pointsFrom(j.at("crossingPoints"));
  r.widthM = numberFrom(j.at("width"));
  r.firstScan = integerFrom(j.at("first"));
  r.lastScan = integerFrom(j.at("last"));
  r.lastPose = poseFrom(j.at("lastPose"));
  r.support = integerFrom(j.at("support"));
  r.traversals = integerFrom(j.at("traversals"));
  return r;
}

}  // namespace rgnav
