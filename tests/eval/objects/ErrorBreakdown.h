// ErrorBreakdown: where the errors of a matched map come from, for the report. A false detection
// either overlaps a counted ground-truth blob too little (a poor footprint: IoU < the
// threshold) or lies off furniture: on the building (walls, pillars: cells occupied in the world
// that belong to no blob) or on free space. A missed blob was never hit by a beam of the tour,
// or hit but no detection overlaps it, or overlapped only poorly.
#pragma once

#include <cstddef>
#include <vector>

#include "core/raster/OccupancyGrid.h"
#include "tests/eval/objects/Detection.h"
#include "tests/eval/objects/FurnitureTruth.h"
#include "tests/eval/objects/Matching.h"

namespace rgnav {

struct ErrorBreakdown {
  std::size_t falseOnBlob = 0;      // overlaps a counted blob, IoU too small
  std::size_t falseOnBuilding = 0;  // most of its cells are building
  std::size_t falseElsewhere = 0;
  std::size_t missedUnseen = 0;     // no cell of the blob was hit by a beam
  std::size_t missedUndetected = 0; // hit, but no detection overlaps it
  std::size_t missedPoorFit = 0;    // overlapped by a detection with IoU below the threshold

  ErrorBreakdown& operator+=(const ErrorBreakdown& o);
};

// `hitCells`: the cells a laser return fell into (DetectionSummary::hitCells).
ErrorBreakdown breakDownErrors(const std::vector<Detection>& detections, const MatchResult& match,
                               const FurnitureTruth& truth, const OccupancyGrid& world,
                               const std::vector<bool>& hitCells);

}  // namespace rgnav
