// Greedy IoU matching of detections to furniture blobs; see Matching.h.
#include "tests/eval/objects/Matching.h"

#include <algorithm>
#include <map>
#include <tuple>

namespace rgnav {

MatchResult matchDetections(const std::vector<Detection>& detections, const FurnitureTruth& truth, double minIoU) {
  struct Pair {
    double iou;
    std::size_t detection;
    int blob;
  };
  std::vector<Pair> pairs;
  for (std::size_t d = 0; d < detections.size(); ++d) {
    const std::vector<std::size_t>& cells = detections[d].cells;
    std::map<int, std::size_t> shared;
    for (const std::size_t cell : cells)
      if (const int blob = truth.blobOfCell[cell]; blob >= 0) ++shared[blob];
    for (const auto& [blob, n] : shared) {
      const std::size_t blobCells = truth.blobs[static_cast<std::size_t>(blob)].cells.size();
      const double iou = static_cast<double>(n) / static_cast<double>(cells.size() + blobCells - n);
      if (iou >= minIoU) pairs.push_back({iou, d, blob});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    return std::tie(b.iou, a.detection, a.blob) < std::tie(a.iou, b.detection, b.blob);
  });

  MatchResult result;
  result.outcomes.assign(detections.size(), Outcome::kFalse);
  result.detectionOfBlob.assign(truth.blobs.size(), -1);
  std::vector<bool> taken(detections.size(), false);
  for (const Pair& p : pairs) {
    const bool excluded = truth.blobs[static_cast<std::size_t>(p.blob)].exclusion != Exclusion::kNone;
    if (excluded && !taken[p.detection]) result.outcomes[p.detection] = Outcome::kIgnored;
    if (taken[p.detection] || result.detectionOfBlob[static_cast<std::size_t>(p.blob)] >= 0) continue;
    taken[p.detection] = true;
    result.detectionOfBlob[static_cast<std::size_t>(p.blob)] = static_cast<int>(p.detection);
    if (!excluded) result.outcomes[p.detection] = Outcome::kMatch;
  }
  for (const FurnitureBlob& blob : truth.blobs) result.truthObjects += blob.exclusion == Exclusion::kNone;
  for (std::size_t d = 0; d < detections.size(); ++d) {
    if (result.outcomes[d] == Outcome::kIgnored) continue;
    const auto kind = static_cast<std::size_t>(detections[d].kind);
    ++result.detections;
    ++result.detectionsByKind[kind];
    if (result.outcomes[d] == Outcome::kMatch) {
      ++result.matches;
      ++result.matchesByKind[kind];
    }
  }
  return result;
}

}  // namespace rgnav
