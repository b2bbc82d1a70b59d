// The global consistency check of an RG Map; see RgMapConsistency.h.
#include "core/rgmap/kernel/RgMapConsistency.h"

#include <map>
#include <set>

namespace rgnav {
namespace {

std::string regionName(RegionId id) { return "region " + std::to_string(id.value()); }
std::string gatewayName(GatewayId id) { return "gateway " + std::to_string(id.value()); }

void checkGateway(const RgMapState& s, const Gateway& g, std::vector<std::string>& out) {
  const std::string name = gatewayName(g.id);
  const std::size_t crossings = g.record.crossingPoints.size();
  const bool narrow = g.record.kind == GatewayKind::NarrowPassage;
  if (crossings != (narrow ? 2u : 4u) || g.record.gatewayPoints.size() != crossings)
    out.push_back(name + ": wrong number of gateway or crossing points");
  for (std::size_t side : {kSideA, kSideB}) {
    const GatewaySideRef& ref = g.sides[side];
    const std::string sideName = name + " side " + (side == kSideA ? "A" : "B");
    if (narrow && ref.crossing != side) out.push_back(sideName + ": a narrow passage's side is its crossing point");
    if (ref.crossing != kNoCrossing && ref.crossing >= crossings) out.push_back(sideName + ": no such crossing point");
    if (!ref.region.isNone() && ref.crossing == kNoCrossing) out.push_back(sideName + ": a region without a crossing point");
    if (ref.region.isNone()) continue;
    const auto r = s.regions.find(ref.region);
    if (r == s.regions.end())
      out.push_back(sideName + " names " + regionName(ref.region) + ", which does not exist");
    else if (!r->second.gateways.contains(g.id))
      out.push_back(sideName + " names " + regionName(ref.region) + ", which does not list it");
  }
  if (g.sides[kSideA].crossing != kNoCrossing && g.sides[kSideA].crossing == g.sides[kSideB].crossing)
    out.push_back(name + ": both sides on the same crossing point");
  const bool same = !g.sides[kSideA].region.isNone() && g.sides[kSideA].region == g.sides[kSideB].region;
  if (same != g.neutralised)
    out.push_back(name +
                  (same ? ": the same region on both sides but not neutralised" : ": neutralised but joins two sides"));
}

void checkRegion(const RgMapState& s, const Region& r, std::vector<std::string>& out) {
  const std::string name = regionName(r.id);
  if (r.scans.empty() && r.id != s.current) out.push_back(name + ": empty");
  for (std::size_t i = 0; i < r.scans.size(); ++i) {
    if (i > 0 && r.scans[i] <= r.scans[i - 1]) out.push_back(name + ": scans not ascending");
    if (!s.scans.contains(r.scans[i])) out.push_back(name + ": scan " + std::to_string(r.scans[i]) + " is not stored");
  }
  for (GatewayId id : r.gateways) {
    const auto g = s.gateways.find(id);
    if (g == s.gateways.end())
      out.push_back(name + " lists " + gatewayName(id) + ", which does not exist");
    else if (g->second.sides[kSideA].region != r.id && g->second.sides[kSideB].region != r.id)
      out.push_back(name + " lists " + gatewayName(id) + ", which does not name it");
  }
}

}  // namespace

std::vector<std::string> checkConsistency(const RgMapState& s) {
  std::vector<std::string> out;
  std::set<DetectorGatewayId> detectorIds;
  for (const auto& [id, g] : s.gateways) {
    if (g.id != id || id.isNone() || id >= s.nextGatewayId) out.push_back(gatewayName(id) + ": bad ID");
    for (const DetectorGatewayId detectorId : g.aliases)
      if (detectorId == g.record.id || !detectorIds.insert(detectorId).second)
        out.push_back(gatewayName(id) + ": detector gateway " + std::to_string(detectorId.value()) + " is mapped twice");
    if (!detectorIds.insert(g.record.id).second)
      out.push_back(gatewayName(id) + ": detector gateway " + std::to_string(g.record.id.value()) + " is mapped twice");
    if (!g.aliases.empty() && !g.door()) out.push_back(gatewayName(id) + ": a hallway area with further detector IDs");
    checkGateway(s, g, out);
  }

  std::map<DataId, std::size_t> regionsOfScan;
  std::map<std::string, RegionId> names, objectNames;
  for (const auto& [id, r] : s.regions) {
    if (r.id != id || id.isNone() || id >= s.nextRegionId) out.push_back(regionName(id) + ": bad ID");
    checkRegion(s, r, out);
    for (DataId scan : r.scans) ++regionsOfScan[scan];
    if (!r.name.empty() && !names.emplace(r.name, id).second)
      out.push_back(regionName(id) + ": name \"" + r.name + "\" is taken by " + regionName(names.at(r.name)));
    for (const auto& [name, at] : r.objectNames)
      if (name.empty() || !objectNames.emplace(name, id).second)
        out.push_back(regionName(id) + ": object name \"" + name + "\" is empty or taken");
  }
  for (const auto& [id, stored] : s.scans) {
    const std::size_t n = regionsOfScan.contains(id) ? regionsOfScan.at(id) : 0;
    if (n != 1) out.push_back("scan " + std::to_string(id) + " lies in " + std::to_string(n) + " regions");
    if (stored.scan.id != id || id > s.lastScanId) out.push_back("scan " + std::to_string(id) + ": bad ID");
  }

  if (!s.current.isNone() ? !s.regions.contains(s.current) : !s.regions.empty())
    out.push_back("the current " + regionName(s.current) + " does not exist");
  for (std::size_t i = 0; i < s.events.size(); ++i)
    if (s.events[i].id != i + 1) out.push_back("event " + std::to_string(s.events[i].id) + " out of sequence");
  return out;
}

}  // namespace rgnav
