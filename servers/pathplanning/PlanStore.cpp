// The PathPlanning module's latest plans and their checkpoint (see PlanStore.h).
#include "servers/pathplanning/PlanStore.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/common/JsonForms.h"

namespace rgnav {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "rgnav-plans";
constexpr int kVersion = 1;

json nodeJson(const GraphNodeView& n) {
  return {{"gateway", n.gateway}, {"side", n.side}, {"region", n.region}, {"position", jsonPoint(n.position)}};
}

GraphNodeView nodeFrom(const json& j) {
  return {integerFrom(j.at("gateway")), integerFrom(j.at("side")), integerFrom(j.at("region")), pointFrom(j.at("position"))};
}

json planJson(const PlanRecord& r) {
  json targets = json::array(), route = json::array();
  for (const TargetPose& t : r.plan.targets) targets.push_back({{"pose", jsonPose(t.pose)}, {"region", t.region}});
  for (const GraphNodeView& n : r.plan.route) route.push_back(nodeJson(n));
  return {{"id", r.id},
          {"request", r.request},
          {"start", jsonPose(r.start)},
          {"goal", planGoalJson(r.goal)},
          {"targets", targets},
          {"route", route},
          {"path", jsonPoints(r.plan.path)},
          {"length", jsonNumber(r.plan.lengthM)},
          {"startRegion", r.plan.startRegion},
          {"goalRegion", r.plan.goalRegion},
          {"mapRevision", r.plan.mapRevision}};
}

PlanRecord planFrom(const json& j) {
  PlanRecord r;
  r.id = integerFrom(j.at("id"));
  r.request = integerFrom(j.at("request"));
  r.start = poseFrom(j.at("start"));
  r.goal = planGoalFrom(j.at("goal"));
  for (const json& t : j.at("targets")) r.plan.targets.push_back({poseFrom(t.at("pose")), integerFrom(t.at("region"))});
  for (const json& n : j.at("route")) r.plan.route.push_back(nodeFrom(n));
  r.plan.path = pointsFrom(j.at("path"));
  r.plan.lengthM = numberFrom(j.at("length"));
  r.plan.startRegion = integerFrom(j.at("startRegion"));
  r.plan.goalRegion = integerFrom(j.at("goalRegion"));
  r.plan.mapRevision = integerFrom(j.at("mapRevision"));
  return r;
}

}  // namespace

json planGoalJson(const PlanGoal& g) {
  return {{"kind", static_cast<int>(g.kind)}, {"point", jsonPoint(g.point)}, {"region", g.region}, {"name", g.name}};
}

PlanGoal planGoalFrom(const json& j) {
  const int kind = integerFrom(j.at("kind"));
  if (kind < 0 || kind > static_cast<int>(PlanGoal::Kind::Object))
    throw FormatError("<checkpoint>", 0, "unknown goal kind " + std::to_string(kind));
  return {static_cast<PlanGoal::Kind>(kind), pointFrom(j.at("point")), integerFrom(j.at("region")),
          j.at("name").get<std::string>()};
}

PlanStore::PlanStore(std::size_t kept) : kept_(std::max<std::size_t>(kept, 1)) {}

void PlanStore::add(PlanRecord plan) {
  if (plan.id != nextId_)
    throw InvalidArgumentError("plan " + std::to_string(plan.id) + " is not the next plan " + std::to_string(nextId_));
  nextId_ = plan.id + 1;
  plans_.push_back(std::move(plan));
  while (plans_.size() > kept_) plans_.pop_front();
}

const PlanRecord* PlanStore::byId(PlanId id) const {
  const auto found = std::find_if(plans_.begin(), plans_.end(), [id](const PlanRecord& p) { return p.id == id; });
  return found == plans_.end() ? nullptr : &*found;
}

const PlanRecord* PlanStore::byRequest(std::uint64_t request) const {
  const auto found =
      std::find_if(plans_.begin(), plans_.end(), [request](const PlanRecord& p) { return p.request == request; });
  return found == plans_.end() ? nullptr : &*found;
}

std::string PlanStore::serialize() const {
  json plans = json::array();
  for (const PlanRecord& p : plans_) plans.push_back(planJson(p));
  return json{{"format", kFormat}, {"version", kVersion}, {"nextId", nextId_}, {"plans", plans}}.dump() + "\n";
}

PlanStore PlanStore::deserialize(const std::string& text, const std::string& source, std::size_t kept) {
  return readingJson(source, [&] {
    const json j = json::parse(text);
    if (j.at("format") != kFormat || j.at("version") != kVersion)
      throw FormatError(source, 0, std::string("not a ") + kFormat + " version " + std::to_string(kVersion) + " file");
    PlanStore store(kept);
    const std::vector<json> plans = j.at("plans").get<std::vector<json>>();
    if (!plans.empty()) store.nextId_ = planFrom(plans.front()).id;
    for (const json& p : plans) store.add(planFrom(p));
    store.nextId_ = std::max<PlanId>(store.nextId_, integerFrom(j.at("nextId")));
    return store;
  });
}

}  // namespace rgnav
