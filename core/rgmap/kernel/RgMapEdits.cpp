// Primitive changes of an RG Map; see RgMapEdits.h.
#include "core/rgmap/kernel/RgMapEdits.h"

#include <algorithm>
#include <iterator>

namespace rgnav {
namespace {

using K = RgMapEventKind;

// Re-flags `g` after one of its sides changed; announces a gateway that became neutralised.
void updateNeutralised(RgMapState& s, Gateway& g, DataId scan) {
  const bool same = !g.sides[kSideA].region.isNone() && g.sides[kSideA].region == g.sides[kSideB].region;
  if (same && !g.neutralised) emitEvent(s, K::GatewayNeutralised, g.sides[kSideA].region, RegionId{}, g.id, scan);
  g.neutralised = same;
}

// Takes `g` off `region`'s list unless another of its sides still lies there.
void unlist(RgMapState& s, const Gateway& g, RegionId region) {
  if (region.isNone() || g.sides[kSideA].region == region || g.sides[kSideB].region == region) return;
  s.regions.at(region).gateways.erase(g.id);
}

}  // namespace

void emitEvent(RgMapState& s, RgMapEventKind kind, RegionId region, RegionId other, GatewayId gateway, DataId scan) {
  s.events.push_back({s.events.size() + 1, kind, region, other, gateway, scan});
}

RegionId createRegion(RgMapState& s, const Pose2D& frame, DataId scan) {
  const RegionId id = s.nextRegionId++;
  s.regions.emplace(id, Region{id, frame, {}, {}, {}, false, {}});
  emitEvent(s, K::RegionCreated, id, RegionId{}, GatewayId{}, scan);
  return id;
}

GatewayId addGateway(RgMapState& s, const GatewayRecord& record, const Pose2D& odomToMap, DataId scan) {
  const GatewayId id = s.nextGatewayId++;
  Gateway g{id, record, odomToMap, {}, {}, false, {}};
  if (record.kind == GatewayKind::NarrowPassage) {
    g.sides[kSideA].crossing = 0;
    g.sides[kSideB].crossing = 1;
  }
  s.gateways.emplace(id, std::move(g));
  emitEvent(s, K::GatewayAdded, RegionId{}, RegionId{}, id, scan);
  return id;
}

void attachSide(RgMapState& s, GatewayId id, std::size_t side, RegionId region, DataId scan) {
  Gateway& g = s.gateways.at(id);
  const RegionId old = g.sides[side].region;
  if (old == region) return;
  g.sides[side].region = region;
  g.sides[side].attachedAt = scan;
  unlist(s, g, old);
  s.regions.at(region).gateways.insert(id);
  emitEvent(s, K::GatewayAttached, region, old, id, scan);
  updateNeutralised(s, g, scan);
}

RegionId mergeRegions(RgMapState& s, RegionId a, RegionId b, DataId scan) {
  const RegionId keepId = std::min(a, b), goneId = std::max(a, b);
  Region& keep = s.regions.at(keepId);
  Region gone = std::move(s.regions.at(goneId));
  s.regions.erase(goneId);

  std::vector<DataId> scans;
  std::merge(keep.scans.begin(), keep.scans.end(), gone.scans.begin(), gone.scans.end(), std::back_inserter(scans));
  keep.scans = std::move(scans);
  if (keep.name.empty()) keep.name = gone.name;
  keep.objectNames.merge(gone.objectNames);
  keep.finalised = keep.finalised || gone.finalised;
  for (GatewayId id : gone.gateways) {
    Gateway& g = s.gateways.at(id);
    for (GatewaySideRef& ref : g.sides)
      if (ref.region == goneId) ref.region = keepId;
    keep.gateways.insert(id);
  }
  if (s.current == goneId) s.current = keepId;
  emitEvent(s, K::RegionsMerged, keepId, goneId, GatewayId{}, scan);
  for (GatewayId id : gone.gateways) updateNeutralised(s, s.gateways.at(id), scan);
  return keepId;
}

RegionId unmergeRegions(RgMapState& s, const RevertibleMerge& m, DataId scan) {
  Region& kept = s.regions.at(m.kept.id);
  const std::vector<DataId> since(std::upper_bound(kept.scans.begin(), kept.scans.end(), m.lastScan), kept.scans.end());
  kept = m.kept;
  Region absorbed = m.absorbed;
  std::vector<DataId>& robots = m.current == absorbed.id ? absorbed.scans : kept.scans;
  robots.insert(robots.end(), since.begin(), since.end());
  for (const auto& [id, before] : m.sides)
    for (std::size_t side : {kSideA, kSideB})
      if (before[side] == absorbed.id) s.gateways.at(id).sides[side].region = absorbed.id;
  if (s.current == kept.id && m.current == absorbed.id) s.current = absorbed.id;
  s.regions.emplace(absorbed.id, std::move(absorbed));
  emitEvent(s, K::RegionsUnmerged, m.kept.id, m.absorbed.id, GatewayId{}, scan);
  for (const auto& [id, before] : m.sides) updateNeutralised(s, s.gateways.at(id), scan);
  return m.absorbed.id;
}

void moveScans(RgMapState& s, RegionId from, RegionId to, DataId first, DataId end) {
  std::vector<DataId>& source = s.regions.at(from).scans;
  const auto lo = std::lower_bound(source.begin(), source.end(), first);
  const auto hi = std::lower_bound(lo, source.end(), end);
  std::vector<DataId>& target = s.regions.at(to).scans;
  std::vector<DataId> merged;
  std::merge(target.begin(), target.end(), lo, hi, std::back_inserter(merged));
  target = std::move(merged);
  source.erase(lo, hi);
}

void removeRegion(RgMapState& s, RegionId region, DataId scan) {
  for (GatewayId id : s.regions.at(region).gateways) {
    Gateway& g = s.gateways.at(id);
    for (GatewaySideRef& ref : g.sides)
      if (ref.region == region) ref = {RegionId{}, ref.crossing, 0};
    updateNeutralised(s, g, scan);
  }
  s.regions.erase(region);
  emitEvent(s, K::RegionRemoved, region, RegionId{}, GatewayId{}, scan);
}

void dropGateway(RgMapState& s, GatewayId id, DataId scan) {
  const Gateway& g = s.gateways.at(id);
  for (const GatewaySideRef& ref : g.sides)
    if (!ref.region.isNone()) s.regions.at(ref.region).gateways.erase(id);
  s.gateways.erase(id);
  emitEvent(s, K::GatewayDropped, RegionId{}, RegionId{}, id, scan);
}

}  // namespace rgnav
