// The RG Mapping Kernel's rules; see RgMappingKernel.h.
#include "core/rgmap/kernel/RgMappingKernel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "core/common/Errors.h"
#include "core/gateways/passages/PassageEndsDistance.h"
#include "core/gateways/passages/SegmentCrossing.h"
#include "core/lines/ScanPoints.h"
#include "core/rgmap/kernel/DoorSeparation.h"
#include "core/rgmap/kernel/KernelInputs.h"
#include "core/rgmap/kernel/ObjectNames.h"
#include "core/rgmap/kernel/RgMapConsistency.h"
#include "core/rgmap/kernel/RgMapEdits.h"
#include "core/rgmap/kernel/RgMapGraph.h"
#include "core/rgmap/kernel/RevertibleMerges.h"

namespace rgnav {
namespace {

using K = RgMapEventKind;

constexpr DataId kNoScanLimit = std::numeric_limits<DataId>::max();

std::size_t otherSide(std::size_t side) { return side == kSideA ? kSideB : kSideA; }

// The robot pose where it crossed the gateway (map frame): at the traversal point, heading across.
Pose2D crossingPose(const TraversalReport& t, const Pose2D& odomToMap) {
  const Eigen::Vector2d at = transformPoint(odomToMap, t.at);
  return {at.x(), at.y(), normalizeAngle(std::atan2(t.direction.y(), t.direction.x()) + odomToMap.theta)};
}

// Whether the sight line from the robot to crossing point `crossing` of gateway `id` passes
// through the line of another door that is not neutralised (map frame).
bool seenThroughAnotherDoor(const RgMapState& state, GatewayId id, const Eigen::Vector2d& robot,
                            std::size_t crossing) {
  const Eigen::Vector2d target = placeGateway(state.gateways.at(id)).crossingPoints[crossing];
  for (const auto& [other, gateway] : state.gateways) {
    if (other == id || !gateway.door() || gateway.neutralised) continue;
    const PlacedGateway placed = placeGateway(gateway);
    if (segmentCrossing(robot, target, placed.gatewayPoints[0], placed.gatewayPoints[1])) return true;
  }
  return false;
}

// Whether the robot's last passage went through gateway `id` into `region`: a traversal, or a
// repaired missed traversal (which may have merged the region it made into the one beyond).
bool lastPassageInto(const RgMapState& state, GatewayId id, RegionId region) {
  const auto last = std::find_if(state.events.rbegin(), state.events.rend(), [](const RgMapEvent& e) {
    return e.kind == K::GatewayTraversed || e.kind == K::GatewayRepaired;
  });
  if (last == state.events.rend() || last->gateway != id) return false;
  return last->kind == K::GatewayRepaired || last->other == region;
}

// Whether one gateway has region `a` on one side and region `b` on the other.
bool shareGateway(const RgMapState& state, RegionId a, RegionId b) {
  const std::set<GatewayId>& ofB = state.regions.at(b).gateways;
  return std::ranges::any_of(state.regions.at(a).gateways, [&](GatewayId g) { return ofB.contains(g); });
}

}  // namespace

RgMappingKernel::RgMappingKernel(const RgMappingKernelConfig& config) : config_(config), models_(config.models) {
  validate(config.costs);
  validate(config.separation);
  if (!(config.sameDoorM >= 0.0)) throw ConfigError("RG mapping kernel: sameDoorM must be >= 0");
}

RgMappingKernel::RgMappingKernel(const RgMappingKernelConfig& config, RgMapState state) : RgMappingKernel(config) {
  const std::vector<std::string> violations = rgnav::checkConsistency(state);
  if (!violations.empty()) throw InvalidArgumentError("inconsistent RG map: " + violations.front());
  costTable(state, config.costs);  // throws for a learned cost the table refuses
  state_ = std::move(state);
  keepLatestMerges(state_, config_.revertibleMerges);
}

void RgMappingKernel::ensureCurrentRegion(const Pose2D& frame, DataId scan) {
  if (!state_.current.isNone()) return;
  state_.current = createRegion(state_, frame, scan);
  state_.visitStart = 0;
}

void RgMappingKernel::addScan(const LaserScan& scan, const Pose2D& corrected) {
  if (scan.id <= state_.lastScanId)
    throw InvalidArgumentError("scan " + std::to_string(scan.id) + " is not after scan " +
                               std::to_string(state_.lastScanId));
  requireFinite(corrected, "scan " + std::to_string(scan.id));
  ensureCurrentRegion(corrected, scan.id);
  state_.scans.emplace(scan.id, StoredScan{scan, corrected});
  state_.regions.at(state_.current).scans.push_back(scan.id);
  state_.lastScanId = scan.id;
  repairPassedDoor(corrected, scan.id);
}

void RgMappingKernel::repairPassedDoor(const Pose2D& robot, DataId scan) {
  const Eigen::Vector2d at(robot.x, robot.y);
  for (const auto& [id, g] : state_.gateways) {
    if (!g.door() || g.neutralised) continue;
    const std::optional<std::size_t> crossing = robotCrossing(g, at, config_.sides);
    if (!crossing || seenThroughAnotherDoor(state_, id, at, *crossing)) continue;
    for (std::size_t side : {kSideA, kSideB}) {
      const GatewaySideRef& ref = g.sides[side];
      if (ref.crossing != *crossing || ref.region.isNone() || ref.region == state_.current) continue;
      if (repairMissedCrossing(id, side, scan + 1)) return;  // the gateways changed: no further look
    }
  }
}

void RgMappingKernel::addGatewayEvent(const GatewayEvent& event, const Pose2D& lastScanCorrected) {
  const std::string what = "gateway event " + std::to_string(event.id);
  if (event.id <= state_.lastGatewayEventId)
    throw InvalidArgumentError(what + " is not after event " + std::to_string(state_.lastGatewayEventId));
  validateGatewayEvent(event);
  requireFinite(lastScanCorrected, what);
  state_.lastGatewayEventId = event.id;
  const DataId scan = event.kind == GatewayEventKind::Traversed ? event.traversal.scanId : event.gateway.lastScan;
  ensureCurrentRegion(lastScanCorrected, scan);
  const Pose2D odomToMap = odometryToMap(event.gateway, lastScanCorrected);
  // A traversal of a gateway whose label is no transition (a passage superseded in the very scan
  // the robot crossed it) is taken as the relabelling it is.
  if (event.kind == GatewayEventKind::Traversed && event.gateway.isTransition())
    traverse(event, odomToMap);
  else
    observe(event, odomToMap, lastScanCorrected);
  models_.prune(state_);
}

std::optional<GatewayId> RgMappingKernel::findGateway(DetectorGatewayId detectorId) const {
  for (const auto& [id, g] : state_.gateways)
    if (g.record.id == detectorId || std::find(g.aliases.begin(), g.aliases.end(), detectorId) != g.aliases.end())
      return id;
  return std::nullopt;
}

std::optional<GatewayId> RgMappingKernel::sameDoorAs(const GatewayRecord& record, const Pose2D& odomToMap) const {
  if (record.kind != GatewayKind::NarrowPassage) return std::nullopt;
  Gateway seen;
  seen.record = record;
  seen.odomToMap = odomToMap;
  const PlacedGateway placed = placeGateway(seen);
  std::optional<GatewayId> nearest;
  double nearestM = config_.sameDoorM;
  for (const auto& [id, g] : state_.gateways) {
    if (!g.door() || !g.record.isTransition()) continue;
    const PlacedGateway known = placeGateway(g);
    const double d = passageEndsDistance(known.gatewayPoints[0], known.gatewayPoints[1], placed.gatewayPoints[0],
                                         placed.gatewayPoints[1])
                         .distanceM;
    if (d <= nearestM) {
      nearest = id;
      nearestM = d;
    }
  }
  return nearest;
}

std::size_t RgMappingKernel::crossingOf(GatewayId id, const GatewayRecord& record, const Pose2D& odomToMap,
                                        std::size_t k) const {
  const Gateway& g = state_.gateways.at(id);
  if (g.record.id == record.id) return k;
  return nearestCrossing(placeGateway(g), transformPoint(odomToMap, record.crossingPoints.at(k)));
}

GatewayId RgMappingKernel::takeIn(const GatewayRecord& record, const Pose2D& odomToMap, bool announceUpdate,
                                  DataId scan) {
  std::optional<GatewayId> known = findGateway(record.id);
  if (!known) {
    known = sameDoorAs(record, odomToMap);
    if (!known) return addGateway(state_, record, odomToMap, scan);
    state_.gateways.at(*known).aliases.push_back(record.id);
    announceUpdate = true;
  }
  Gateway& g = state_.gateways.at(*known);
  if (g.record.id == record.id) {
    g.record = record;
    g.odomToMap = odomToMap;
  }
  if (announceUpdate) emitEvent(state_, K::GatewayUpdated, RegionId{}, RegionId{}, *known, scan);
  return *known;
}

std::optional<std::size_t> RgMappingKernel::sideOf(GatewayId id, std::size_t crossing) {
  Gateway& g = state_.gateways.at(id);
  for (std::size_t side : {kSideA, kSideB})
    if (g.sides[side].crossing == crossing) return side;
  for (std::size_t side : {kSideA, kSideB})
    if (g.sides[side].crossing == kNoCrossing) {
      g.sides[side].crossing = crossing;
      return side;
    }
  return std::nullopt;
}

RegionId RgMappingKernel::joinSide(GatewayId id, std::size_t side, RegionId region, DataId scan) {
  const RegionId there = state_.gateways.at(id).sides[side].region;
  if (there == region) return region;
  if (there.isNone()) {
    attachSide(state_, id, side, region, scan);
    return region;
  }
  return rgnav::mergeRegions(state_, there, region, scan);  // the same place seen twice: a loop closed
}

void RgMappingKernel::observe(const GatewayEvent& event, const Pose2D& odomToMap, const Pose2D& robot) {
  const GatewayRecord& record = event.gateway;
  const DataId scan = record.lastScan;
  if (!record.isTransition()) {
    const std::optional<GatewayId> known = findGateway(record.id);
    if (!known) return;
    Gateway& g = state_.gateways.at(*known);
    if (g.record.id != record.id) {  // an alias: only that track is no gateway, not the door it was matched to
      std::erase(g.aliases, record.id);
      return;
    }
    if (g.traversalsFrom[kSideA] + g.traversalsFrom[kSideB] == 0) {
      dropGateway(state_, *known, scan);
      return;
    }
    takeIn(record, odomToMap, true, scan);
    const RegionId a = g.sides[kSideA].region, b = g.sides[kSideB].region;
    if (!a.isNone() && !b.isNone() && a != b) rgnav::mergeRegions(state_, a, b, scan);
    return;
  }
  const GatewayId id = takeIn(record, odomToMap, event.kind == GatewayEventKind::Updated, scan);
  // A hallway area joins regions only through the traversals the detector reports (see the header).
  if (!state_.gateways.at(id).door()) return;
  const std::optional<std::size_t> crossing = robotCrossing(state_.gateways.at(id), {robot.x, robot.y}, config_.sides);
  if (!crossing || seenThroughAnotherDoor(state_, id, {robot.x, robot.y}, *crossing)) return;
  const std::optional<std::size_t> side = sideOf(id, *crossing);
  if (!side) return;
  repairMissedCrossing(id, *side, kNoScanLimit);
  joinSide(id, *side, state_.current, scan);
}

void RgMappingKernel::traverse(const GatewayEvent& event, const Pose2D& odomToMap) {
  const TraversalReport& t = event.traversal;
  const GatewayId id = takeIn(event.gateway, odomToMap, false, t.scanId);
  if (!state_.gateways.at(id).door() && event.gateway.support < config_.minAreaSequences) {
    emitEvent(state_, K::GatewayTraversed, state_.current, state_.current, id, t.scanId);
    return;
  }
  const std::optional<std::size_t> from = sideOf(id, crossingOf(id, event.gateway, odomToMap, t.fromSide));
  const std::optional<std::size_t> to = sideOf(id, crossingOf(id, event.gateway, odomToMap, t.toSide));
  if (!from || !to) {  // through further sides of a hallway area: no structure (see the header)
    emitEvent(state_, K::GatewayTraversed, state_.current, state_.current, id, t.scanId);
    return;
  }
  // Two tracks of one door (an alias, see the header) both report the robot passing it.
  if (state_.gateways.at(id).sides[*to].region == state_.current && lastPassageInto(state_, id, state_.current))
    return;
  repairMissedCrossing(id, *from, t.scanId);
  ++state_.gateways.at(id).traversalsFrom[*from];
  const Gateway& crossed = state_.gateways.at(id);
  const bool separates = crossed.door() ? separatesSpace(state_, id, config_.separation)
                                        : areaSeparatesSides(state_, id, crossed.sides[*from].crossing,
                                                             crossed.sides[*to].crossing, config_.separation);
  RegionId left = joinSide(id, *from, state_.current, t.scanId);
  if (!separates) left = joinSide(id, *to, left, t.scanId);  // no door: both sides are one region
  RegionId entered = state_.gateways.at(id).sides[*to].region;
  if (entered == left) {  // a neutralised gateway: the robot stays where it is
    emitEvent(state_, K::GatewayTraversed, left, left, id, t.scanId);
    return;
  }
  if (entered.isNone()) {
    entered = createRegion(state_, crossingPose(t, odomToMap), t.scanId);
    attachSide(state_, id, *to, entered, t.scanId);
  } else {
    emitEvent(state_, K::RegionEntered, entered, RegionId{}, GatewayId{}, t.scanId);
  }
  moveScans(state_, left, entered, t.scanId, kNoScanLimit);
  state_.current = entered;
  state_.visitStart = t.scanId;
  emitEvent(state_, K::GatewayTraversed, left, entered, id, t.scanId);
  leave(left, t.scanId);
}

bool RgMappingKernel::repairMissedCrossing(GatewayId id, std::size_t robotSide, DataId before) {
  const RegionId cur = state_.current;
  const Gateway& g = state_.gateways.at(id);
  if (g.sides[robotSide].region == cur) return false;
  std::vector<DataId> visit;
  std::vector<Eigen::Vector2d> path;
  for (DataId s : state_.regions.at(cur).scans)
    if (s >= state_.visitStart && s < before) {
      const Pose2D& p = state_.scans.at(s).corrected;
      visit.push_back(s);
      path.emplace_back(p.x, p.y);
    }
  const std::optional<std::size_t> step = lastPathCrossing(g, path, g.sides[robotSide].crossing);
  if (!step) return false;

  const DataId k = visit[*step];
  const RegionId split = createRegion(state_, state_.scans.at(k).corrected, k);
  moveScans(state_, cur, split, k, before);
  const std::set<GatewayId> attached = state_.regions.at(cur).gateways;
  for (GatewayId other : attached) {
    if (other == id) continue;
    for (std::size_t side : {kSideA, kSideB}) {
      const GatewaySideRef ref = state_.gateways.at(other).sides[side];
      if (ref.region == cur && ref.attachedAt >= k && ref.attachedAt < before)
        attachSide(state_, other, side, split, ref.attachedAt);
    }
  }
  if (!state_.regions.at(cur).objectNames.empty()) {  // descriptions cost time; most regions have no names
    const std::vector<Rectangle2D> curObjects = description(cur).objects;
    moveObjectNames(state_.regions.at(cur), curObjects, state_.regions.at(split), description(split).objects);
  }
  state_.current = split;
  state_.visitStart = k;
  emitEvent(state_, K::GatewayRepaired, cur, split, id, k);
  leave(cur, k);
  joinSide(id, otherSide(robotSide), cur, k);
  joinSide(id, robotSide, split, k);
  return true;
}

void RgMappingKernel::leave(RegionId region, DataId scan) {
  Region& r = state_.regions.at(region);
  if (r.scans.empty()) {
    removeRegion(state_, region, scan);
    return;
  }
  emitEvent(state_, r.finalised ? K::RegionUpdated : K::RegionFinalised, region, RegionId{}, GatewayId{}, scan);
  r.finalised = true;
}

void RgMappingKernel::revisePoses(std::span<const CorrectedPose> poses, std::uint64_t revision) {
  std::map<DataId, Pose2D> revised;
  for (const CorrectedPose& p : poses) {
    requireFinite(p.pose, "revised pose of scan " + std::to_string(p.scanId));
    revised[p.scanId] = p.pose;
  }
  bool changed = false;
  for (const auto& [id, pose] : revised) {
    const auto stored = state_.scans.find(id);
    if (stored == state_.scans.end() || stored->second.corrected == pose) continue;
    stored->second.corrected = pose;
    changed = true;
  }
  for (auto& [id, g] : state_.gateways) {
    const auto pose = revised.find(g.record.lastScan);
    if (pose == revised.end()) continue;
    const Pose2D placed = odometryToMap(g.record, pose->second);
    changed = changed || !(placed == g.odomToMap);
    g.odomToMap = placed;
  }
  state_.lastPoseRevision = revision;
  if (changed) emitEvent(state_, K::PosesRevised, RegionId{}, RegionId{}, GatewayId{}, state_.lastScanId);
}

RegionId RgMappingKernel::mergeRegions(RegionId a, RegionId b, bool force) {
  const std::string pair = "region " + std::to_string(a.value()) + " and region " + std::to_string(b.value());
  if (a == b) throw InvalidArgumentError("cannot merge " + pair + ": they are the same region");
  for (const RegionId r : {a, b})
    if (!state_.regions.contains(r))
      throw InvalidArgumentError("cannot merge " + pair + ": no region " + std::to_string(r.value()));
  if (!force && !shareGateway(state_, a, b))
    throw InvalidArgumentError("cannot merge " + pair + ": they share no gateway (force the merge if they are one place)");
  state_.revertibleMerges.push_back(revertibleMerge(state_, a, b));
  keepLatestMerges(state_, config_.revertibleMerges);
  const RegionId merged = rgnav::mergeRegions(state_, a, b, state_.lastScanId);
  models_.prune(state_);
  return merged;
}

RegionId RgMappingKernel::unmergeRegions(RegionId merged) {
  std::vector<RevertibleMerge>& merges = state_.revertibleMerges;
  const auto latestWith = [&](auto&& which) {
    return std::find_if(merges.rbegin(), merges.rend(), [&](const RevertibleMerge& m) { return which(m) == merged; });
  };
  const auto latest = latestWith([](const RevertibleMerge& m) { return m.kept.id; });
  const std::string region = "region " + std::to_string(merged.value());
  if (latest == merges.rend()) {
    const auto into = latestWith([](const RevertibleMerge& m) { return m.absorbed.id; });
    const std::string hint = into == merges.rend() ? ""
                                                   : " (" + region + " was merged into region " +
                                                         std::to_string(into->kept.id.value()) + ": undo that merge)";
    throw InvalidArgumentError("no merge into " + region + " can be undone: none is among the latest " +
                               std::to_string(config_.revertibleMerges) + " merges on request" + hint);
  }
  if (const std::optional<std::string> why = whyNotRevertible(state_, *latest))
    throw InvalidArgumentError("cannot undo the merge of region " + std::to_string(latest->absorbed.id.value()) +
                               " into " + region + ": " + *why);
  const RevertibleMerge undone = std::move(*latest);
  merges.erase(std::next(latest).base());
  const RegionId restored = rgnav::unmergeRegions(state_, undone, state_.lastScanId);
  models_.prune(state_);
  return restored;
}

void RgMappingKernel::nameRegion(RegionId region, const std::string& name) {
  const auto r = state_.regions.find(region);
  if (r == state_.regions.end()) throw InvalidArgumentError("no region " + std::to_string(region.value()));
  const std::optional<RegionId> holder = regionByName(name);
  if (!name.empty() && holder && *holder != region)
    throw InvalidArgumentError("region " + std::to_string(holder->value()) + " is already named \"" + name + "\"");
  r->second.name = name;
  emitEvent(state_, K::RegionNamed, region, RegionId{}, GatewayId{}, state_.lastScanId);
}

std::optional<RegionId> RgMappingKernel::regionByName(const std::string& name) const {
  for (const auto& [id, r] : state_.regions)
    if (!name.empty() && r.name == name) return id;
  return std::nullopt;
}

void RgMappingKernel::nameObject(RegionId region, const Eigen::Vector2d& atInRegion, const std::string& name) {
  if (!atInRegion.allFinite())
    throw InvalidArgumentError("an object is named at a finite point, not a NaN or infinite one");
  const auto r = state_.regions.find(region);
  if (r == state_.regions.end()) throw InvalidArgumentError("no region " + std::to_string(region.value()));
  const std::vector<Rectangle2D>& objects = description(region).objects;
  const std::optional<std::size_t> index = objectAt(objects, atInRegion);
  if (!index)
    throw InvalidArgumentError("region " + std::to_string(region.value()) + " has no object at (" +
                               std::to_string(atInRegion.x()) + ", " + std::to_string(atInRegion.y()) + ")");
  const auto isThisObject = [&](const Eigen::Vector2d& namedAt) {
    return objectNamedAt(r->second, objects, namedAt) == index;
  };
  const std::optional<NamedObject> holder = objectByName(name);
  if (!name.empty() && holder && !(holder->region == region && isThisObject(holder->namedAt)))
    throw InvalidArgumentError("another object is already named \"" + name + "\"");
  std::erase_if(r->second.objectNames, [&](const auto& entry) { return isThisObject(entry.second); });
  if (!name.empty()) {
    const Pose2D centre = compose(r->second.frame, {objects[*index].pose.x, objects[*index].pose.y, 0.0});
    r->second.objectNames[name] = {centre.x, centre.y};
  }
  emitEvent(state_, K::ObjectNamed, region, RegionId{}, GatewayId{}, state_.lastScanId);
}

std::optional<RgMappingKernel::NamedObject> RgMappingKernel::objectByName(const std::string& name) const {
  for (const auto& [id, r] : state_.regions) {
    const auto found = r.objectNames.find(name);
    if (found != r.objectNames.end()) return NamedObject{id, found->second};
  }
  return std::nullopt;
}

void RgMappingKernel::recordEdgeTraversal(const EdgeKey& edge, double lengthM, double timeS) {
  RgGraph g = graph();
  g.recordTraversal(edge, lengthM, timeS);
  storeCosts(state_, g.costs());
  emitEvent(state_, K::CostsLearned, RegionId{}, RegionId{}, edge.a.gateway, state_.lastScanId);
}

void RgMappingKernel::recordDoorState(GatewayId gateway, bool traversable) {
  RgGraph g = graph();
  g.recordDoorState(gateway, traversable);
  storeCosts(state_, g.costs());
  emitEvent(state_, K::CostsLearned, RegionId{}, RegionId{}, gateway, state_.lastScanId);
}

CurrentRegion RgMappingKernel::currentRegion() const {
  if (state_.current.isNone()) throw NotAvailableError("no region yet");
  const RegionLineMap& lines = models_.lineMap(state_, state_.current);
  return {state_.regions.at(state_.current), lines, models_.description(state_, state_.current)};
}

const RegionLineMap& RgMappingKernel::lineMap(RegionId region) const { return models_.lineMap(state_, region); }

const RegionDescription& RgMappingKernel::description(RegionId region) const {
  return models_.description(state_, region);
}

PlacedGateway RgMappingKernel::gatewayInRegion(GatewayId gateway, RegionId region) const {
  const auto g = state_.gateways.find(gateway);
  const auto r = state_.regions.find(region);
  if (g == state_.gateways.end() || r == state_.regions.end())
    throw NotAvailableError("no gateway " + std::to_string(gateway.value()) + " or region " + std::to_string(region.value()));
  return placeGateway(g->second, r->second.frame);
}

std::vector<RgMapEvent> RgMappingKernel::eventsSince(RgMapEventId afterId) const {
  if (afterId >= state_.events.size()) return {};
  return {state_.events.begin() + static_cast<std::ptrdiff_t>(afterId), state_.events.end()};
}

RgGraph RgMappingKernel::graph() const {
  RgGraph g(costTable(state_, config_.costs));
  g.build(graphSpec(state_));
  return g;
}

std::vector<std::string> RgMappingKernel::checkConsistency() const { return rgnav::checkConsistency(state_); }

}  // namespace rgnav
