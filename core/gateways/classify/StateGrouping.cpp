// Left-right HMM states from clusters by distance interval (thesis 4.1.3.3, table 4.1; see
// StateGrouping.h).
#include "core/gateways/classify/StateGrouping.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

// Linear interpolation between the order statistics of sorted values.
double quantileOf(const std::vector<double>& sorted, double q) {
  const double position = q * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = position - static_cast<double>(below);
  return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

}  // namespace

ClusterDistances summariseDistances(std::vector<double> distances, double quantile) {
  if (distances.empty()) throw InvalidArgumentError("cluster without distances");
  if (!(quantile >= 0.0 && quantile <= 0.5)) throw InvalidArgumentError("distance quantile must lie in [0, 0.5]");
  std::sort(distances.begin(), distances.end());
  const double mean = std::accumulate(distances.begin(), distances.end(), 0.0) / static_cast<double>(distances.size());
  return {mean, quantileOf(distances, quantile), quantileOf(distances, 1.0 - quantile)};
}

double overlapFraction(const ClusterDistances& a, const ClusterDistances& b) {
  const double shorter = std::min(a.high - a.low, b.high - b.low);
  const double overlap = std::min(a.high, b.high) - std::max(a.low, b.low);
  if (shorter <= 0.0) return overlap >= 0.0 ? 1.0 : 0.0;
  return std::max(overlap, 0.0) / shorter;
}

std::vector<std::vector<std::size_t>> groupByDistanceInterval(const std::vector<ClusterDistances>& clusters,
                                                              double minOverlap) {
  std::vector<std::size_t> order(clusters.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&clusters](std::size_t a, std::size_t b) { return clusters[a].mean > clusters[b].mean; });
  std::vector<std::vector<std::size_t>> states;
  for (const std::size_t c : order) {
    const auto overlapsEnough = [&](std::size_t member) {
      return overlapFraction(clusters[member], clusters[c]) >= minOverlap;
    };
    if (!states.empty() && std::all_of(states.back().begin(), states.back().end(), overlapsEnough)) {
      states.back().push_back(c);
    } else {
      states.push_back({c});
    }
  }
  return states;
}

}  // namespace rgnav
