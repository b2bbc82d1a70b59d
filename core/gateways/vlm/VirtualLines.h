// VirtualLines: thesis 4.1.1.1, "line segments from L_LS which lie approximately on the same
// line are grouped and represented by that line, also referred to as virtual line". The line
// scan comes from core/lines (LineExtractor); segments are taken longest first and each joins
// the group whose line it lies on (angle and endpoint offsets within limits) or starts a new one;
// a group's line is the TLS fit of all points of its segments (their PointMoments added).
// Unlike LineMerger (3.1.1) there is no gap limit: a virtual line spans the openings of a
// crossing. Our addition: groups with less segment length than minSupportM are dropped (the
// thesis gives no such limit; single short pieces of clutter would multiply the hypotheses).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "core/gateways/vlm/PlanarLine.h"
#include "core/lines/LineSegment.h"

namespace rgnav {

struct VirtualLineParams {
  double maxAngleRad = 5.0 * M_PI / 180.0;  // segment direction vs. the group's line
  double maxOffsetM = 0.08;                 // segment endpoints from the group's line
  double minSupportM = 0.3;                 // total segment length of a kept virtual line
};

template <class V>
void describe(V& v, VirtualLineParams& c) {
  v.degrees("max_angle_deg", c.maxAngleRad);
  v.field("max_offset_m", c.maxOffsetM);
  v.field("min_support_m", c.minSupportM);
}

struct VirtualLine {
  PlanarLine line;
  double supportM = 0.0;  // total length of its segments
  std::size_t segmentCount = 0;
};

// Throws InvalidArgumentError for negative limits or an angle limit of 90 degrees or more.
std::vector<VirtualLine> groupVirtualLines(std::vector<LineSegment> segments, const VirtualLineParams& params = {});

}  // namespace rgnav
