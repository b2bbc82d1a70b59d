// EdgeCostTable: learned edge costs of the RG Graph (thesis 5.4); see EdgeCostTable.h.
#include "core/rgmap/graph/EdgeCostTable.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

void requireNonNegative(double value, const std::string& what) {
  if (!std::isfinite(value) || value < 0.0)
    throw InvalidArgumentError(what + " must be finite and >= 0, got " + std::to_string(value));
}

void requireFinite(double value, const char* name) {
  if (!std::isfinite(value)) throw ConfigError(std::string("edge costs: ") + name + " must be finite");
}

}  // namespace

void validate(const EdgeCostConfig& config) {
  requireFinite(config.nominalSpeedMps, "nominalSpeedMps");
  requireFinite(config.doorBlockedM, "doorBlockedM");
  requireFinite(config.doorOpenM, "doorOpenM");
  requireFinite(config.doorExtraM, "doorExtraM");
  if (config.nominalSpeedMps <= 0.0) throw ConfigError("edge costs: nominalSpeedMps must be > 0");
  if (config.traversalMemory == 0) throw ConfigError("edge costs: traversalMemory must be >= 1");
  if (config.doorBlockedM <= 0.0) throw ConfigError("edge costs: doorBlockedM must be > 0");
  if (config.doorOpenM > 0.0) throw ConfigError("edge costs: doorOpenM must be <= 0");
  if (config.doorExtraM < 0.0) throw ConfigError("edge costs: doorExtraM must be >= 0");
}

EdgeCostTable::EdgeCostTable(const EdgeCostConfig& config) : config_(config) { validate(config_); }

void EdgeCostTable::recordTraversal(const EdgeKey& edge, double lengthM, double timeS) {
  requireNonNegative(lengthM, "traversal length of " + toString(edge));
  requireNonNegative(timeS, "traversal time of " + toString(edge));
  const double value = std::max(lengthM, timeS * config_.nominalSpeedMps);
  TraversalStats& stats = traversals_[edge];
  ++stats.count;
  const double weight = 1.0 / static_cast<double>(std::min(stats.count, config_.traversalMemory));
  stats.meanM += weight * (value - stats.meanM);
}

void EdgeCostTable::recordDoorState(GatewayId g, bool traversable) {
  double& offset = doorOffsets_[g];
  offset = std::max(0.0, offset + (traversable ? config_.doorOpenM : config_.doorBlockedM));
}

double EdgeCostTable::cost(const EdgeKey& edge, double lengthM, bool doorEdge) const {
  requireNonNegative(lengthM, "length of " + toString(edge));
  double base = lengthM;
  if (const auto t = traversals_.find(edge); t != traversals_.end()) base = std::max(base, t->second.meanM);
  if (!doorEdge) return base;
  double offset = 0.0;
  if (const auto d = doorOffsets_.find(edge.a.gateway); d != doorOffsets_.end()) offset = d->second;
  return std::max(base, lengthM + config_.doorExtraM) + offset;
}

void EdgeCostTable::restoreTraversal(const EdgeKey& edge, const TraversalStats& stats) {
  requireNonNegative(stats.meanM, "restored mean of " + toString(edge));
  if (stats.count == 0) throw InvalidArgumentError("restored traversals of " + toString(edge) + " must count >= 1");
  traversals_[edge] = stats;
}

void EdgeCostTable::restoreDoorOffset(GatewayId g, double offsetM) {
  requireNonNegative(offsetM, "restored door offset of gateway " + std::to_string(g.value()));
  doorOffsets_[g] = offsetM;
}

}  // namespace rgnav
