// Removal of hypotheses that overlap better ones. Hypotheses are visited best score first; one
// is kept unless its overlap with an already kept one exceeds maxOverlapRatio, measured as
// - kShareOfOwnArea: intersection / own area, so a contained hypothesis always goes (thesis 3.2:
//   "deleting all hypotheses that are contained in others or strongly overlap"), or
// - kIntersectionOverUnion: intersection / union, so only near-duplicates go and an object
//   inside a larger hypothesis (a table inside a room) stays.
#pragma once

#include <cstddef>
#include <vector>

#include "core/objects/ConvexPolygon.h"

namespace rgnav {

enum class OverlapMeasure { kShareOfOwnArea, kIntersectionOverUnion };

// Indices of the kept hypotheses, best score first (ties: lower index first). `outlines` are
// convex, counter-clockwise, one per score.
std::vector<std::size_t> suppressOverlaps(const std::vector<Polygon>& outlines, const std::vector<double>& scores,
                                          OverlapMeasure measure, double maxOverlapRatio);

}  // namespace rgnav
