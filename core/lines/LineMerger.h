// LineMerger: merging of 2D line segments, thesis 3.1.1. Segments are sorted once by their
// angle to the x-axis; each is compared only with those above it in the sorted array within the
// angle window maxAngleRad (alpha_max, circularly, since 0 and pi are the same orientation).
// For such a pair, D_L is the mean of the four distances of each endpoint to the other
// segment's line (figure 3.3); if D_L <= maxLineDistanceM (D_L^max) and the segments overlap
// along the common line or leave a gap D_gap <= maxGapM (D_gap^max), they are merged: the new
// segment runs between the two endpoints (of the four) farthest apart, projected onto the line
// fitted to both. The merged segment keeps the smaller ID and the union of the provenance, so
// `unmerge` can give back the original segments (3.3.1).
// Deliberate differences: the merged line is the TLS fit of all points of both segments (see
// PointMoments.h), where the thesis only fixes the endpoints; a sweep merges greedily and sweeps
// are repeated (re-sorting) until one merges nothing, so the result has no mergeable pair left
// (usually two sweeps).
#pragma once

#include <optional>
#include <vector>

#include "core/lines/LineSegment.h"

namespace rgnav {

struct LineMergerParams {                   // thesis 3.2, laser data
  double maxAngleRad = 3.0 * M_PI / 180.0;  // alpha_max
  double maxLineDistanceM = 0.020;          // D_L^max
  double maxGapM = 0.150;                   // D_gap^max
};

template <class V>
void describe(V& v, LineMergerParams& c) {
  v.degrees("max_angle_deg", c.maxAngleRad);
  v.field("max_line_distance_m", c.maxLineDistanceM);
  v.field("max_gap_m", c.maxGapM);
}

// D_L of figure 3.3: mean distance of the four endpoints to the other segment's line.
double lineDistance(const LineSegment& a, const LineSegment& b);

// Signed gap between the segments along the direction of the longer one: > 0 is the distance
// between their nearest endpoints along that line, <= 0 means they overlap.
double gapAlongLine(const LineSegment& a, const LineSegment& b);

class LineMerger {
 public:
  // Throws InvalidArgumentError for negative thresholds or alpha_max >= 90 degrees.
  explicit LineMerger(const LineMergerParams& params = {});

  // The merge of a and b if the thesis rules allow it.
  std::optional<LineSegment> tryMerge(const LineSegment& a, const LineSegment& b) const;

  // All segments after merging until no pair can be merged, sorted by orientation.
  std::vector<LineSegment> merge(std::vector<LineSegment> segments) const;

 private:
  // One sweep over the angle-sorted segments; returns the number of merges done.
  std::size_t sweep(std::vector<LineSegment>& segments) const;

  LineMergerParams params_;
};

// The original segments (out of `originals`) that `merged` was made of, in provenance order.
// Throws NotAvailableError if one of them is not in `originals`.
std::vector<LineSegment> unmerge(const LineSegment& merged, const std::vector<LineSegment>& originals);

}  // namespace rgnav
