// Classification of false detections and missed blobs; see ErrorBreakdown.h.
#include "tests/eval/objects/ErrorBreakdown.h"

#include <algorithm>

namespace rgnav {

ErrorBreakdown& ErrorBreakdown::operator+=(const ErrorBreakdown& o) {
  falseOnBlob += o.falseOnBlob;
  falseOnBuilding += o.falseOnBuilding;
  falseElsewhere += o.falseElsewhere;
  missedUnseen += o.missedUnseen;
  missedUndetected += o.missedUndetected;
  missedPoorFit += o.missedPoorFit;
  return *this;
}

ErrorBreakdown breakDownErrors(const std::vector<Detection>& detections, const MatchResult& match,
                               const FurnitureTruth& truth, const OccupancyGrid& world,
                               const std::vector<bool>& hitCells) {
  const auto counted = [&](std::size_t cell) {
    const int blob = truth.blobOfCell[cell];
    return blob >= 0 && truth.blobs[static_cast<std::size_t>(blob)].exclusion == Exclusion::kNone;
  };
  ErrorBreakdown e;
  std::vector<bool> overlapped(truth.blobs.size(), false);
  for (std::size_t d = 0; d < detections.size(); ++d) {
    const std::vector<std::size_t>& cells = detections[d].cells;
    for (const std::size_t c : cells)
      if (const int blob = truth.blobOfCell[c]; blob >= 0) overlapped[static_cast<std::size_t>(blob)] = true;
    if (match.outcomes[d] != Outcome::kFalse) continue;
    const auto building = std::count_if(cells.begin(), cells.end(), [&](std::size_t c) {
      return truth.blobOfCell[c] < 0 && world.cells()[c] != Cell::Free;
    });
    if (std::any_of(cells.begin(), cells.end(), counted))
      ++e.falseOnBlob;
    else if (2 * static_cast<std::size_t>(building) > cells.size())
      ++e.falseOnBuilding;
    else
      ++e.falseElsewhere;
  }
  for (std::size_t b = 0; b < truth.blobs.size(); ++b) {
    const FurnitureBlob& blob = truth.blobs[b];
    if (blob.exclusion != Exclusion::kNone || match.detectionOfBlob[b] >= 0) continue;
    if (std::none_of(blob.cells.begin(), blob.cells.end(), [&](std::size_t c) { return hitCells[c]; }))
      ++e.missedUnseen;
    else if (!overlapped[b])
      ++e.missedUndetected;
    else
      ++e.missedPoorFit;
  }
  return e;
}

}  // namespace rgnav
