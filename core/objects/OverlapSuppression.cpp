// Overlap suppression; see OverlapSuppression.h.
#include "core/objects/OverlapSuppression.h"

#include <algorithm>
#include <numeric>

#include "core/common/Errors.h"

namespace rgnav {

std::vector<std::size_t> suppressOverlaps(const std::vector<Polygon>& outlines, const std::vector<double>& scores,
                                          OverlapMeasure measure, double maxOverlapRatio) {
  if (outlines.size() != scores.size()) throw InvalidArgumentError("suppressOverlaps: one score per outline needed");
  std::vector<std::size_t> order(outlines.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return scores[a] > scores[b]; });
  std::vector<double> area(outlines.size());
  for (std::size_t i = 0; i < outlines.size(); ++i) area[i] = polygonArea(outlines[i]);
  std::vector<std::size_t> kept;
  for (const std::size_t i : order) {
    const bool covered = std::any_of(kept.begin(), kept.end(), [&](std::size_t k) {
      const double common = intersectionArea(outlines[i], outlines[k]);
      const double base = measure == OverlapMeasure::kShareOfOwnArea ? area[i] : area[i] + area[k] - common;
      return common > maxOverlapRatio * base;
    });
    if (!covered) kept.push_back(i);
  }
  return kept;
}

}  // namespace rgnav
