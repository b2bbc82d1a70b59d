// LocalizationMap (LocalizationMap.h): regions, the gateways between them, and the cached fields.
#include "core/nav/localization/LocalizationMap.h"

#include <algorithm>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

Eigen::Vector2d apply(const Pose2D& frame, const Eigen::Vector2d& p) {
  const Pose2D q = compose(frame, Pose2D{p.x(), p.y(), 0.0});
  return {q.x, q.y};
}

Segment2 transformed(const Pose2D& frame, const Segment2& s) { return {apply(frame, s.a), apply(frame, s.b)}; }

}  // namespace

LocalizationMap::LocalizationMap(const BeamModelConfig& config) : config_(config) {
  MclConfig whole;
  whole.beam = config;
  validate(whole);
}

void LocalizationMap::setRegion(LocalizationRegion region) {
  const RegionId id = region.id;
  regions_[id] = std::move(region);
}

void LocalizationMap::removeRegion(RegionId id) {
  regions_.erase(id);
  fields_.erase(id);
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
}

LocalizationMap LocalizationMap::fromViews(const std::vector<RegionView>& regions,
                                           const std::vector<GatewayView>& gateways, const BeamModelConfig& config) {
  LocalizationMap map(config);
  for (const RegionView& r : regions)
    map.setRegion({r.summary.id, r.summary.frame, r.summary.scans, r.lines, r.freespace, r.summary.gateways});
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
  return it->second;
}

std::vector<RegionId> LocalizationMap::regionIds() const {
  std::vector<RegionId> ids;
  for (const auto& [id, r] : regions_) ids.push_back(id);
  return ids;
}

std::vector<RegionId> LocalizationMap::neighbours(RegionId id) const {
  std::vector<RegionId> out;
  for (const GatewayId g : region(id).gateways) {
    const auto it = gateways_.find(g);
    if (it == gateways_.end()) continue;
    for (const RegionId side : it->second.regions)
      if (side != id && regions_.count(side) && std::find(out.begin(), out.end(), side) == out.end()) out.push_back(side);
  }
  return out;
}

const LikelihoodField& LocalizationMap::field(RegionId id) const {
  const LocalizationRegion& own = region(id);
  const std::vector<RegionId> stacked = neighbours(id);
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
  if (it == regions_.end()) return from;
  for (const GatewayId id : it->second.gateways) {
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
  const auto holds = [&](const LocalizationRegion& r) { return r.freespace.isFreeAt(apply(inverse(r.frame), p)); };
  const auto it = regions_.find(hint);
  if (it != regions_.end() && holds(it->second)) return hint;
  for (const auto& [id, r] : regions_)
    if (holds(r)) return id;
  return RegionId{};
}

std::size_t LocalizationMap::fieldBytes() const {
  std::size_t bytes = 0;
  for (const auto& [id, f] : fields_)
    if (f.field) bytes += f.field->bytes();
  return bytes;
}

}  // namespace rgnav
