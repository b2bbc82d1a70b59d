// Line extraction from one scan; see LineExtractor.h.
#include "core/lines/LineExtractor.h"

#include "core/common/Errors.h"
#include "core/lines/SplitAndMerge.h"

namespace rgnav {

LineExtractor::LineExtractor(const LineExtractorParams& params) : params_(params) {
  if (!(params.splitDistanceM > 0.0) || params.minPoints < 2 || !(params.minLengthM >= 0.0))
    throw InvalidArgumentError("line extractor: splitDistanceM > 0, minPoints >= 2 and minLengthM >= 0 required");
}

std::vector<LineSegment> LineExtractor::extract(const std::vector<ScanPoint>& points, double angleIncrementRad,
                                                SegmentId firstId) const {
  std::vector<LineSegment> segments;
  std::vector<Eigen::Vector2d> run;
  for (const auto& [first, last] : splitAtBreakpoints(points, angleIncrementRad, params_.breakpoints)) {
    run.clear();
    for (std::size_t i = first; i < last; ++i) run.push_back(points[i].position);
    for (const auto& [a, b] : splitAndMerge(run, params_.splitDistanceM)) {
      if (b - a < params_.minPoints) continue;
      LineSegment segment = segmentFromPoints(firstId + segments.size(), std::span(run).subspan(a, b - a));
      if (segment.length() >= params_.minLengthM) segments.push_back(std::move(segment));
    }
  }
  return segments;
}

std::vector<LineSegment> LineExtractor::extract(const LaserScan& scan, const Pose2D& sensorPose,
                                                SegmentId firstId) const {
  return extract(scanPoints(scan, sensorPose), scan.angleIncrement, firstId);
}

}  // namespace rgnav
