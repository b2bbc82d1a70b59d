// LocalizationMap (LocalizationMap.h): regions, the gateways between them, and the cached fields.
#include "core/nav/localization/LocalizationMap.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {
namespace {

Segment2 transformed(const Pose2D& frame, const Segment2& s) { return {transformPoint(frame, s.a), transformPoint(frame, s.b)}; }

}  // namespace

LocalizationRegion localizationRegion(const RegionView& r) {
  return {r.summary.id, r.summary.frame, r.summary.scans, r.lines, r.freespace, r.summary.gateways};
}

LocalizationMap::LocalizationMap(const BeamModelConfig& config) : config_(config) {
  MclConfig whole;
  whole.beam = config;
  validate(whole);
}

void LocalizationMap::setRegion(LocalizationRegion region) {
  const RegionId id = region.id;
  const Pose2D& f = region.frame;
  regions_[id] = {std::move(region), {std::cos(f.theta), std::sin(f.theta), f.x, f.y}, {}, std::nullopt};
  relink();
}

void LocalizationMap::removeRegion(RegionId id) {
  regions_.erase(id);
  fields_.erase(id);
  relink();
}

void LocalizationMap::relink() {
  for (auto& [id, entry] : regions_) {
    entry.neighbours.clear();
    entry.stacked.reset();
    for (const GatewayId g : entry.region.gateways) {
      const auto it = gateways_.find(g);
      if (it == gateways_.end()) continue;
      for (const RegionId side : it->second.regions)
        if (side != id && regions_.count(side) &&
            std::find(entry.neighbours.begin(), entry.neighbours.end(), side) == entry.neighbours.end())
          entry.neighbours.push_back(side);
    }
  }
}

void LocalizationMap::setGateways(const std::vector<GatewayView>& gateways) {
  gateways_.clear();
  for (const GatewayView& g : gateways) {
    if (g.neutralised || g.sideA.isNone() || g.sideB.isNone() || g.sideA == g.sideB) continue;
    const std::size_t a = g.sideCrossings[0], b = g.sideCrossings[1];
    if (a >= g.crossingPoints.size() || b >= g.crossingPoints.size() || a == b) continue;
    LocalizationGateway kept{g.id, {g.sideA, g.sideB}, {g.crossingPoints[a], g.crossingPoints[b]}, {}};
    kept.centre = (kept.crossingPoints[0] + kept.crossingPoints[1]) / 2.0;
    gateways_[g.id] = kept;
  }
  relink();
}

LocalizationMap LocalizationMap::fromViews(const std::vector<RegionView>& regions,
                                           const std::vector<GatewayView>& gateways, const BeamModelConfig& config) {
  LocalizationMap map(config);
  for (const RegionView& r : regions) map.setRegion(localizationRegion(r));
  map.setGateways(gateways);
  return map;
}

LocalizationMap LocalizationMap::wholeFloor(const std::vector<RegionView>& regions, const BeamModelConfig& config) {
  LocalizationRegion floor{RegionId{1}, Pose2D{}, 1, {}, {}, {}};
  for (const RegionView& r : regions)
    for (const Segment2& s : r.lines) floor.lines.push_back(transformed(r.summary.frame, s));
  LocalizationMap map(config);
  map.setRegion(std::move(floor));
  return map;
}

const LocalizationRegion& LocalizationMap::region(RegionId id) const {
  const auto it = regions_.find(id);
  if (it == regions_.end()) throw NotAvailableError("LocalizationMap: no region " + std::to_string(id.value()));
  return it->second.region;
}

std::vector<RegionId> LocalizationMap::regionIds() const {
  std::vector<RegionId> ids;
  for (const auto& [id, r] : regions_) ids.push_back(id);
  return ids;
}

const LikelihoodField& LocalizationMap::field(RegionId id) const {
  const LocalizationRegion& own = region(id);
  const std::vector<RegionId>& stacked = stackedWith(regions_.at(id));
  std::vector<std::pair<RegionId, std::uint64_t>> key{{id, own.revision}};
  for (const RegionId n : stacked) key.emplace_back(n, region(n).revision);
  CachedField& cached = fields_[id];
  if (!cached.field || cached.key != key) {
    std::vector<Segment2> lines = own.lines;
    const Pose2D toOwn = inverse(own.frame);
    for (const RegionId n : stacked) {
      const LocalizationRegion& other = region(n);
      const Pose2D otherToOwn = compose(toOwn, other.frame);
      for (const Segment2& s : other.lines) lines.push_back(transformed(otherToOwn, s));
    }
    cached.field = std::make_unique<LikelihoodField>(lines, config_);
    cached.key = std::move(key);
  }
  return *cached.field;
}

RegionId LocalizationMap::handOver(RegionId from, const Eigen::Vector2d& p, double radiusM) const {
  const auto it = regions_.find(from);
  if (it == regions_.end() || holds(it->second, p)) return from;
  for (const RegionId n : it->second.neighbours)
    if (holds(regions_.at(n), p)) return n;
  for (const auto& [id, entry] : regions_)
    if (id != from && holds(entry, p)) return id;
  for (const GatewayId id : it->second.region.gateways) {
    const auto g = gateways_.find(id);
    if (g == gateways_.end()) continue;
    const LocalizationGateway& gw = g->second;
    if ((p - gw.centre).squaredNorm() > radiusM * radiusM) continue;
    const std::size_t own = gw.regions[0] == from ? 0 : 1;
    const RegionId other = gw.regions[1 - own];
    if (!regions_.count(other)) continue;
    if ((p - gw.crossingPoints[1 - own]).squaredNorm() < (p - gw.crossingPoints[own]).squaredNorm()) return other;
  }
  return from;
}

RegionId LocalizationMap::regionAt(const Eigen::Vector2d& p, RegionId hint) const {
  const auto it = regions_.find(hint);
  if (it != regions_.end() && holds(it->second, p)) return hint;
  for (const auto& [id, entry] : regions_)
    if (holds(entry, p)) return id;
  return RegionId{};
}

bool LocalizationMap::freeIn(RegionId id, const Eigen::Vector2d& p) const {
  const auto it = regions_.find(id);
  return it != regions_.end() && holds(it->second, p);
}

bool LocalizationMap::holds(const Entry& entry, const Eigen::Vector2d& p) const {
  return entry.region.freespace.isFreeAt(entry.toRegion(p));
}

const std::vector<RegionId>& LocalizationMap::stackedWith(const Entry& entry) const {
  if (!entry.stacked) {
    std::vector<RegionId> stacked = entry.neighbours;
    for (const RegionId o : overlapping(entry.region.id))
      if (std::find(stacked.begin(), stacked.end(), o) == stacked.end()) stacked.push_back(o);
    entry.stacked = std::move(stacked);
  }
  return *entry.stacked;
}

std::vector<RegionId> LocalizationMap::overlapping(RegionId id) const {
  const Entry& own = regions_.at(id);
  std::vector<RegionId> out;
  for (const auto& [otherId, entry] : regions_) {
    if (otherId == id) continue;
    const LocalizationRegion& other = entry.region;
    const Pose2D otherToMap = other.frame;
    std::size_t shared = 0;
    for (int row = 0; row < other.freespace.height && shared < config_.overlapMinCells; ++row)
      for (int col = 0; col < other.freespace.width && shared < config_.overlapMinCells; ++col)
        if (other.freespace.isFree(col, row) && holds(own, transformPoint(otherToMap, other.freespace.cellCenter(col, row))))
          ++shared;
    if (shared >= config_.overlapMinCells) out.push_back(otherId);
  }
  return out;
}

std::size_t LocalizationMap::fieldBytes() const {
  std::size_t bytes = 0;
  for (const auto& [id, f] : fields_)
    if (f.field) bytes += f.field->bytes();
  return bytes;
}

}  // namespace rgnav
