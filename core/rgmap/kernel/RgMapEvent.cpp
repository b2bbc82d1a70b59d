// Names of the RG Map's event kinds; see RgMapEvent.h.
#include "core/rgmap/kernel/RgMapEvent.h"

#include <array>
#include <utility>

namespace rgnav {
namespace {

using K = RgMapEventKind;

constexpr std::array<std::pair<K, std::string_view>, 18> kNames = {{
    {K::RegionCreated, "RegionCreated"},
    {K::RegionEntered, "RegionEntered"},
    {K::RegionFinalised, "RegionFinalised"},
    {K::RegionUpdated, "RegionUpdated"},
    {K::RegionsMerged, "RegionsMerged"},
    {K::RegionsUnmerged, "RegionsUnmerged"},
    {K::RegionRemoved, "RegionRemoved"},
    {K::RegionNamed, "RegionNamed"},
    {K::ObjectNamed, "ObjectNamed"},
    {K::GatewayAdded, "GatewayAdded"},
    {K::GatewayUpdated, "GatewayUpdated"},
    {K::GatewayAttached, "GatewayAttached"},
    {K::GatewayTraversed, "GatewayTraversed"},
    {K::GatewayNeutralised, "GatewayNeutralised"},
    {K::GatewayRepaired, "GatewayRepaired"},
    {K::GatewayDropped, "GatewayDropped"},
    {K::PosesRevised, "PosesRevised"},
    {K::CostsLearned, "CostsLearned"},
}};

}  // namespace

std::string_view eventKindName(RgMapEventKind kind) {
  for (const auto& [k, name] : kNames)
    if (k == kind) return name;
  return "unknown";
}

std::optional<RgMapEventKind> parseEventKind(std::string_view name) {
  for (const auto& [k, n] : kNames)
    if (n == name) return k;
  return std::nullopt;
}

}  // namespace rgnav
