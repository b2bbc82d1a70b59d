// The cluster bootstrap of the lowest class rate; see LayoutBootstrap.h.
#include "tests/eval/crossings/LayoutBootstrap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

void checkInput(const std::vector<std::vector<GatewayTally>>& groups, int resamples, double level) {
  if (groups.empty()) throw InvalidArgumentError("layout bootstrap without groups");
  for (const std::vector<GatewayTally>& group : groups) {
    if (group.empty()) throw InvalidArgumentError("layout bootstrap: a group without test gateways");
    for (const GatewayTally& g : group)
      if (g.sequences == 0 || g.correct > g.sequences)
        throw InvalidArgumentError("layout bootstrap: a gateway without sequences or with too many correct ones");
  }
  if (resamples < 1) throw InvalidArgumentError("layout bootstrap needs at least one resample");
  if (!(level > 0.0 && level < 1.0)) throw InvalidArgumentError("layout bootstrap level must lie in (0, 1)");
}

// The value below which `share` of the sorted values lie (nearest rank).
double quantile(const std::vector<double>& sorted, double share) {
  const double rank = std::ceil(share * static_cast<double>(sorted.size()));
  const auto index = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(sorted.size())));
  return sorted[index - 1];
}

}  // namespace

RateInterval bootstrapLowestRate(const std::vector<std::vector<GatewayTally>>& groups, int resamples, double level,
                                 std::uint64_t seed) {
  checkInput(groups, resamples, level);
  std::mt19937_64 rng(seed);
  std::vector<double> lowest;
  for (int r = 0; r < resamples; ++r) {
    double minimum = std::numeric_limits<double>::infinity();
    for (const std::vector<GatewayTally>& group : groups) {
      std::uniform_int_distribution<std::size_t> pick(0, group.size() - 1);
      std::size_t correct = 0, sequences = 0;
      for (std::size_t i = 0; i < group.size(); ++i) {
        const GatewayTally& g = group[pick(rng)];
        correct += g.correct;
        sequences += g.sequences;
      }
      minimum = std::min(minimum, static_cast<double>(correct) / static_cast<double>(sequences));
    }
    lowest.push_back(minimum);
  }
  std::sort(lowest.begin(), lowest.end());
  const double tail = (1.0 - level) / 2.0;
  return {quantile(lowest, tail), quantile(lowest, 1.0 - tail)};
}

}  // namespace rgnav
