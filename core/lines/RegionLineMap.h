// RegionLineMap: the 2D line segment map of one region, built incrementally from aligned scans
// (thesis 5.2, "Generating 2D line segment maps from laser data"): after each scan is added,
// its line segments are extracted and merged into the map (3.1.1), so the map stays compact.
// The support of a map line is the number of scan segments merged into it.
#pragma once

#include <cstddef>
#include <vector>

#include "core/lines/LineExtractor.h"
#include "core/lines/LineMerger.h"

namespace rgnav {

class RegionLineMap {
 public:
  explicit RegionLineMap(const LineExtractorParams& extractor = {}, const LineMergerParams& merger = {});

  // Adds `scan` taken with the sensor at `sensorPose` (its aligned pose in the region frame).
  void addScan(const LaserScan& scan, const Pose2D& sensorPose);

  // The merged lines, sorted by orientation. Scan segments get IDs 1, 2, 3, ... in the order
  // extracted; a map line carries the smallest ID of its parts.
  const std::vector<LineSegment>& lines() const { return lines_; }
  std::size_t scanCount() const { return scans_; }
  std::size_t pointCount() const { return points_; }        // valid scan points added
  std::size_t segmentCount() const { return nextId_ - 1; }  // scan segments extracted

 private:
  LineExtractor extractor_;
  LineMerger merger_;
  std::vector<LineSegment> lines_;
  std::size_t scans_ = 0;
  std::size_t points_ = 0;
  SegmentId nextId_ = 1;
};

}  // namespace rgnav
