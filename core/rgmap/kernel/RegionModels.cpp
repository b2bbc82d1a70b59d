// Cached line maps and descriptions of the regions; see RegionModels.h.
#include "core/rgmap/kernel/RegionModels.h"

#include <algorithm>

#include "core/common/Errors.h"
#include "core/rgmap/kernel/DoorSides.h"
#include "core/rgmap/kernel/GatewayGeometry.h"

namespace rgnav {
namespace {

bool sameSegments(const std::vector<GatewaySegment>& a, const std::vector<GatewaySegment>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const GatewaySegment& u, const GatewaySegment& v) { return u.a == v.a && u.b == v.b; });
}

// Whether `doorInMap`, a door no region is attached to, still separates `region` from another
// one: `region`'s robot stood on one side of it only, and another region saw it from the other.
bool separatesFromAnother(const RgMapState& state, const Region& region, const GatewaySegment& doorInMap,
                          const DoorSideProbe& probe, double noReturnFreeRangeM) {
  const unsigned stood = sidesStoodOn(state, region, doorInMap, probe);
  if (stood != kLeftSide && stood != kRightSide) return false;
  const unsigned beyond = kBothSides & ~stood;
  return std::any_of(state.regions.begin(), state.regions.end(), [&](const auto& entry) {
    return entry.first != region.id &&
           (sidesSeenFrom(state, entry.second, doorInMap, probe, noReturnFreeRangeM) & beyond) != 0;
  });
}

}  // namespace

std::vector<GatewaySegment> regionGatewaySegments(const RgMapState& state, const Region& region) {
  std::vector<GatewaySegment> out;
  for (GatewayId id : region.gateways) {
    const Gateway& g = state.gateways.at(id);
    for (std::size_t side : {kSideA, kSideB})
      if (g.sides[side].region == region.id)
        for (const GatewaySegment& s : sideSegments(g, side, region.frame)) out.push_back(s);
  }
  return out;
}

std::vector<GatewaySegment> otherDoorLines(const RgMapState& state, const Region& region, const DoorSideProbe& probe,
                                          double noReturnFreeRangeM) {
  std::vector<GatewaySegment> out;
  for (const auto& [id, gateway] : state.gateways) {
    const bool own = std::any_of(gateway.sides.begin(), gateway.sides.end(),
                                 [&](const GatewaySideRef& side) { return side.region == region.id; });
    if (!gateway.door() || gateway.neutralised || own) continue;
    const bool attached = std::any_of(gateway.sides.begin(), gateway.sides.end(),
                                      [](const GatewaySideRef& side) { return !side.region.isNone(); });
    if (!attached) {
      const PlacedGateway inMap = placeGateway(gateway);
      const GatewaySegment line{inMap.gatewayPoints[0], inMap.gatewayPoints[1]};
      if (!separatesFromAnother(state, region, line, probe, noReturnFreeRangeM)) continue;
    }
    const PlacedGateway placed = placeGateway(gateway, region.frame);
    out.push_back({placed.gatewayPoints[0], placed.gatewayPoints[1]});
  }
  return out;
}

std::vector<GatewaySegment> otherAreaLines(const RgMapState& state, const Region& region) {
  std::vector<GatewaySegment> out;
  for (const auto& [id, gateway] : state.gateways) {
    const RegionId a = gateway.sides[kSideA].region, b = gateway.sides[kSideB].region;
    if (gateway.door() || gateway.neutralised || a.isNone() || b.isNone() || a == region.id || b == region.id) continue;
    const std::vector<Eigen::Vector2d> corners = placeGateway(gateway, region.frame).gatewayPoints;
    for (std::size_t k = 0; k < corners.size(); ++k) out.push_back({corners[k], corners[(k + 1) % corners.size()]});
  }
  return out;
}

std::vector<OwnDoor> ownDoors(const RgMapState& state, const Region& region) {
  std::vector<OwnDoor> out;
  for (GatewayId id : region.gateways) {
    const Gateway& g = state.gateways.at(id);
    if (!g.door() || g.neutralised) continue;
    const std::size_t own = g.sides[kSideA].region == region.id ? kSideA : kSideB;
    const PlacedGateway placed = placeGateway(g, region.frame);
    out.push_back({{placed.gatewayPoints[0], placed.gatewayPoints[1]},
                   (placed.crossingPoints[g.sides[1 - own].crossing] - placed.crossingPoints[g.sides[own].crossing])
                       .normalized()});
  }
  return out;
}

std::vector<GatewaySegment> doorFrameLines(std::span<const OwnDoor> doors, const DoorFrameCut& cut) {
  std::vector<GatewaySegment> out;
  for (const OwnDoor& door : doors) {
    const Eigen::Vector2d along = (door.line.b - door.line.a).normalized();
    const Eigen::Vector2d beyond = cut.depthM * door.away;
    out.push_back({door.line.a + beyond - cut.widenM * along, door.line.b + beyond + cut.widenM * along});
  }
  return out;
}

namespace {

// Where `sensor` lies with respect to `door`: how far past its line (negative: in front of it) and
// how far beside its ends (negative: between them).
struct DoorOffset {
  double past = 0.0;
  double beside = 0.0;
};

DoorOffset offsetFrom(const OwnDoor& door, const Eigen::Vector2d& sensor) {
  const double length = (door.line.b - door.line.a).norm();
  const Eigen::Vector2d along = (door.line.b - door.line.a) / length;
  const Eigen::Vector2d offset = sensor - 0.5 * (door.line.a + door.line.b);
  return {offset.dot(door.away), std::abs(offset.dot(along)) - 0.5 * length};
}

}  // namespace

std::vector<GatewaySegment> doorWallLines(std::span<const OwnDoor> doors, const Eigen::Vector2d& sensor,
                                          const DoorWallCut& cut) {
  std::vector<GatewaySegment> out;
  for (const OwnDoor& door : doors) {
    if (!((door.line.b - door.line.a).norm() > 0.0)) continue;
    const DoorOffset at = offsetFrom(door, sensor);
    if (at.past > 0.0 || at.past < -cut.frontM || at.beside > cut.besideM) continue;
    const Eigen::Vector2d along = (door.line.b - door.line.a).normalized();
    out.push_back({door.line.a - cut.wallM * along, door.line.b + cut.wallM * along});
  }
  return out;
}

bool pastOwnDoor(std::span<const OwnDoor> doors, const Eigen::Vector2d& sensor, const PastOwnDoor& limits) {
  return std::any_of(doors.begin(), doors.end(), [&](const OwnDoor& door) {
    const DoorOffset at = offsetFrom(door, sensor);
    return at.past > 0.0 && at.past <= limits.depthM && at.beside <= limits.besideM;
  });
}

RegionModels::RegionModels(const RegionModelConfig& config) : config_(config) {
  // Both throw for a bad configuration (ConfigError, InvalidArgumentError), before any region needs them.
  if (!(config.doorFrames.depthM >= 0.0) || !(config.doorFrames.widenM >= 0.0))
    throw ConfigError("region models: door frame depth and widening must be >= 0");
  if (!(config.pastOwnDoors.depthM >= 0.0) || !(config.pastOwnDoors.besideM >= 0.0))
    throw ConfigError("region models: the depth and the margin past own doors must be >= 0");
  if (!(config.doorWalls.frontM >= 0.0) || !(config.doorWalls.besideM >= 0.0) || !(config.doorWalls.wallM >= 0.0))
    throw ConfigError("region models: the door wall cut's distances must be >= 0");
  validate(config.unattachedDoors);
  RegionEvidence{config.evidence};
  RegionLineMap{config.extractor, config.merger};
}

RegionModels::Model& RegionModels::upToDate(const RgMapState& state, RegionId id) {
  const auto region = state.regions.find(id);
  if (region == state.regions.end()) throw NotAvailableError("no region " + std::to_string(id.value()));
  const Region& r = region->second;
  const std::vector<GatewaySegment> gateways = regionGatewaySegments(state, r);
  std::vector<GatewaySegment> cutting = gateways;
  const std::vector<GatewaySegment> others =
      otherDoorLines(state, r, config_.unattachedDoors, config_.evidence.freespace.noReturnFreeRangeM);
  cutting.insert(cutting.end(), others.begin(), others.end());
  const std::vector<GatewaySegment> areas = otherAreaLines(state, r);
  cutting.insert(cutting.end(), areas.begin(), areas.end());
  const std::vector<OwnDoor> doors = ownDoors(state, r);
  const std::vector<GatewaySegment> frames = doorFrameLines(doors, config_.doorFrames);
  cutting.insert(cutting.end(), frames.begin(), frames.end());

  auto it = models_.find(id);
  const auto keyAt = [&](std::size_t i) { return ScanKey{r.scans[i], state.scans.at(r.scans[i]).corrected}; };
  bool reusable = it != models_.end() && it->second.frame == r.frame && sameSegments(it->second.gateways, gateways) &&
                  sameSegments(it->second.cutting, cutting) && it->second.doors == doors &&
                  it->second.scans.size() <= r.scans.size();
  for (std::size_t i = 0; reusable && i < it->second.scans.size(); ++i) reusable = it->second.scans[i] == keyAt(i);
  if (!reusable) {
    if (it != models_.end()) models_.erase(it);
    it = models_
             .emplace(id, Model{r.frame,
                                gateways,
                                cutting,
                                doors,
                                {},
                                RegionLineMap(config_.extractor, config_.merger),
                                RegionEvidence(config_.evidence),
                                std::nullopt})
             .first;
  }
  Model& m = it->second;
  try {
    for (std::size_t i = m.scans.size(); i < r.scans.size(); ++i) {
      const ScanKey key = keyAt(i);
      const Pose2D inRegion = between(r.frame, key.corrected);
      const LaserScan& scan = state.scans.at(key.id).scan;
      const Eigen::Vector2d sensor(inRegion.x, inRegion.y);
      if (!pastOwnDoor(m.doors, sensor, config_.pastOwnDoors)) {
        const std::vector<GatewaySegment> walls = doorWallLines(m.doors, sensor, config_.doorWalls);
        if (walls.empty()) {
          m.evidence.addScan(scan, inRegion, m.cutting);  // the only step that can reject the scan
        } else {
          std::vector<GatewaySegment> cutting = m.cutting;
          cutting.insert(cutting.end(), walls.begin(), walls.end());
          m.evidence.addScan(scan, inRegion, cutting);
        }
      }
      m.lines.addScan(scan, inRegion);
      m.scans.push_back(key);
      m.description.reset();
    }
  } catch (...) {
    models_.erase(id);  // half-extended: the next request starts over
    throw;
  }
  return m;
}

const RegionLineMap& RegionModels::lineMap(const RgMapState& state, RegionId id) { return upToDate(state, id).lines; }

const RegionDescription& RegionModels::description(const RgMapState& state, RegionId id) {
  Model& m = upToDate(state, id);
  if (!m.description) m.description = describeRegion(m.evidence, m.lines.lines(), m.gateways, config_.description);
  return *m.description;
}

void RegionModels::prune(const RgMapState& state) {
  std::erase_if(models_, [&](const auto& entry) { return !state.regions.contains(entry.first); });
}

}  // namespace rgnav
