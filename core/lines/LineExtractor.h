// LineExtractor: the line segments of one laser scan (thesis 5.2, "the scans are converted to
// line scans"): valid points (ScanPoints), breakpoints at depth jumps (BreakpointDetector),
// split-and-merge with a TLS fit per piece (SplitAndMerge), then pieces with too few points or
// too short are dropped. The thesis used ScanStudio for this step and gives no parameters; the
// defaults below suit a SICK LMS (1 cm range noise, 0.5 or 1 degree beams).
#pragma once

#include <vector>

#include "core/lines/BreakpointDetector.h"
#include "core/lines/LineSegment.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {

struct LineExtractorParams {
  BreakpointParams breakpoints;
  double splitDistanceM = 0.05;  // largest distance of a point from its segment's line (5 sigma)
  std::size_t minPoints = 5;     // fewer points: no segment
  double minLengthM = 0.15;      // shorter: no segment
};

template <class V>
void describe(V& v, LineExtractorParams& c) {
  v.section("breakpoints", c.breakpoints);
  v.field("split_distance_m", c.splitDistanceM);
  v.field("min_points", c.minPoints);
  v.field("min_length_m", c.minLengthM);
}

class LineExtractor {
 public:
  // Throws InvalidArgumentError for parameters that can never work.
  explicit LineExtractor(const LineExtractorParams& params = {});

  // Segments of `points` (from scanPoints, in beam order), IDs firstId, firstId + 1, ...
  std::vector<LineSegment> extract(const std::vector<ScanPoint>& points, double angleIncrementRad,
                                   SegmentId firstId) const;
  // Segments of `scan` seen from `sensorPose`, IDs firstId, firstId + 1, ...
  std::vector<LineSegment> extract(const LaserScan& scan, const Pose2D& sensorPose, SegmentId firstId) const;

 private:
  LineExtractorParams params_;
};

}  // namespace rgnav
