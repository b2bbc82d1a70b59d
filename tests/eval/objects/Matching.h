// matchDetections: one-to-one matching of detections to ground-truth furniture blobs by the
// intersection over union of their grid cells. Pairs with IoU >= minIoU are taken greedily,
// highest IoU first, so a blob matches at most one detection and a detection at most one blob.
// A detection whose partner is an excluded blob (a speck, a blob no reachable place sees), or
// that overlaps one with IoU >= minIoU, is ignored: it counts neither as right nor as wrong.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "tests/eval/objects/Detection.h"
#include "tests/eval/objects/FurnitureTruth.h"

namespace rgnav {

enum class Outcome { kMatch, kFalse, kIgnored };

struct MatchResult {
  std::vector<Outcome> outcomes;    // per detection
  std::vector<int> detectionOfBlob; // per blob: the matched detection, or -1
  std::size_t truthObjects = 0;     // blobs without exclusion
  std::size_t detections = 0;       // detections not ignored
  std::size_t matches = 0;
  std::array<std::size_t, kDetectionKinds> detectionsByKind{};  // not ignored
  std::array<std::size_t, kDetectionKinds> matchesByKind{};
};

MatchResult matchDetections(const std::vector<Detection>& detections, const FurnitureTruth& truth, double minIoU);

}  // namespace rgnav
