// Which merges on request can be undone; see RevertibleMerges.h.
#include "core/rgmap/kernel/RevertibleMerges.h"

#include <algorithm>
#include <iterator>

namespace rgnav {
namespace {

std::string regionText(RegionId id) { return "region " + std::to_string(id.value()); }

// The region the merge made of the two (RgMapEdits.h, mergeRegions), before scans were stacked into it.
Region mergedRegion(const RevertibleMerge& m) {
  Region r = m.kept;
  r.scans.clear();
  std::merge(m.kept.scans.begin(), m.kept.scans.end(), m.absorbed.scans.begin(), m.absorbed.scans.end(),
             std::back_inserter(r.scans));
  r.gateways.insert(m.absorbed.gateways.begin(), m.absorbed.gateways.end());
  if (r.name.empty()) r.name = m.absorbed.name;
  r.objectNames.insert(m.absorbed.objectNames.begin(), m.absorbed.objectNames.end());
  r.finalised = r.finalised || m.absorbed.finalised;
  return r;
}

bool eitherRegion(const RevertibleMerge& m, RegionId region) { return region == m.kept.id || region == m.absorbed.id; }

// Whether `m` can be the record of a merge of two regions of this map: what a damaged checkpoint
// could get wrong and an undo would turn into an inconsistent map.
bool fitsTheMap(const RgMapState& s, const RevertibleMerge& m) {
  if (m.kept.id.isNone() || !(m.kept.id < m.absorbed.id) || !(m.absorbed.id < s.nextRegionId) ||
      s.regions.contains(m.absorbed.id))
    return false;
  if (!m.kept.name.empty() && m.kept.name == m.absorbed.name) return false;
  for (const auto& [name, at] : m.absorbed.objectNames)
    if (m.kept.objectNames.contains(name)) return false;
  std::set<GatewayId> gateways = m.kept.gateways;
  gateways.insert(m.absorbed.gateways.begin(), m.absorbed.gateways.end());
  if (m.sides.size() != gateways.size()) return false;
  const auto listed = [](const Region& r, GatewayId g, const std::array<RegionId, 2>& sides) {
    return r.gateways.contains(g) == (sides[kSideA] == r.id || sides[kSideB] == r.id);
  };
  return std::ranges::all_of(m.sides, [&](const auto& entry) {
    return listed(m.kept, entry.first, entry.second) && listed(m.absorbed, entry.first, entry.second);
  });
}

// Why the gateway sides of the merged region `now` are not those the merge made, or nullopt.
std::optional<std::string> changedSides(const RgMapState& s, const RevertibleMerge& m, const Region& now) {
  for (GatewayId g : now.gateways) {
    const auto before = m.sides.find(g);
    const auto gateway = s.gateways.find(g);
    if (before == m.sides.end() || gateway == s.gateways.end())
      return "gateway " + std::to_string(g.value()) + " is not one the merge knew";
    for (std::size_t side : {kSideA, kSideB})
      if (eitherRegion(m, before->second[side]) != (gateway->second.sides[side].region == now.id))
        return std::string("a region was attached to gateway ") + std::to_string(g.value()) + " since";
  }
  return std::nullopt;
}

}  // namespace

RevertibleMerge revertibleMerge(const RgMapState& s, RegionId a, RegionId b) {
  RevertibleMerge m{s.regions.at(std::min(a, b)), s.regions.at(std::max(a, b)), {},
                    s.current, s.visitStart, s.lastScanId};
  for (const Region* r : {&m.kept, &m.absorbed})
    for (GatewayId g : r->gateways) {
      const Gateway& gateway = s.gateways.at(g);
      m.sides[g] = {gateway.sides[kSideA].region, gateway.sides[kSideB].region};
    }
  return m;
}

std::optional<std::string> whyNotRevertible(const RgMapState& s, const RevertibleMerge& m) {
  const RegionId id = m.kept.id;
  const auto found = s.regions.find(id);
  if (found == s.regions.end()) return regionText(id) + " was merged into another region since";
  if (!fitsTheMap(s, m)) return "the record of the merge does not fit the map (a damaged checkpoint)";
  const Region& now = found->second;
  const Region made = mergedRegion(m);
  const auto later = std::upper_bound(now.scans.begin(), now.scans.end(), m.lastScan);
  if (!std::equal(now.scans.begin(), later, made.scans.begin(), made.scans.end()))
    return "scans taken before the merge moved into or out of " + regionText(id) + " since";
  if (now.gateways != made.gateways) return regionText(id) + " gained or lost a gateway since";
  if (const std::optional<std::string> sides = changedSides(s, m, now)) return sides;
  if (now.name != made.name) return regionText(id) + " was renamed since";
  if (now.objectNames != made.objectNames) return "objects of " + regionText(id) + " were named since";
  if (now.finalised != made.finalised || !(now.frame == made.frame))
    return "the robot left " + regionText(id) + " for the first time since";
  const bool robotIn = s.current == id;
  if (robotIn && !(eitherRegion(m, m.current) && s.visitStart == m.visitStart))
    return "the robot entered " + regionText(id) +
           " again since: its scans since cannot be divided between the two regions";
  if (!robotIn && later != now.scans.end())
    return "the robot took scans in " + regionText(id) +
           " and left it since: they cannot be divided between the two regions";
  if (!m.absorbed.name.empty())
    for (const auto& [other, r] : s.regions)
      if (other != id && r.name == m.absorbed.name)
        return regionText(other) + " is named \"" + r.name + "\" since (rename it first)";
  return std::nullopt;
}

void keepLatestMerges(RgMapState& s, std::size_t count) {
  std::vector<RevertibleMerge>& merges = s.revertibleMerges;
  if (merges.size() > count) merges.erase(merges.begin(), merges.end() - static_cast<std::ptrdiff_t>(count));
}

}  // namespace rgnav
