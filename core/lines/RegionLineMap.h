// RegionLineMap: the 2D line segment map of one region, built incrementally from aligned scans
// (thesis 5.2, "Generating 2D line segment maps from laser data"): after each scan is added,
// its line segments are extracted and merged into the map (3.1.1), so the map stays compact.
// The support of a map line is the number of scan segments merged into it.
// Deliberate difference: merging the whole map again after each scan (3.1.1 on all lines) costs
// O(N^2) per scan in a hallway of N lines. Here each new segment is merged, to a fixpoint, only
// with the map lines a LineGrid finds near it (the only ones the 3.1.1 rules can merge it with):
// a merge grows the segment, which is then compared again with the lines near its new extent
// until nothing merges, and joins the map. As the map never holds a mergeable pair, the result
// again has no pair left to merge under the same rules, and the work per scan depends on the
// scan and the lines around it, not on the size of the region. Nearby lines are tried in the
// order a merge sweep meets them (by orientation), but merging is greedy and a full re-merge also
// reconsiders lines the new scan does not touch, so where merges chain (a merges with b and with
// c, a + b no longer with c) the two can split segments differently: the same lines on the
// synthetic test sequences; on Intel keyframes 215-244 the same count (84) with one pair split
// differently; on the whole Intel log as one region 2056 lines against 2058.
#pragma once

#include <cstddef>
#include <vector>

#include "core/lines/LineExtractor.h"
#include "core/lines/LineGrid.h"
#include "core/lines/LineMerger.h"

namespace rgnav {

class RegionLineMap {
 public:
  explicit RegionLineMap(const LineExtractorParams& extractor = {}, const LineMergerParams& merger = {});

  // Adds `scan` taken with the sensor at `sensorPose` (its aligned pose in the region frame).
  // Throws InvalidArgumentError, leaving the map as it was, for a non-finite pose.
  void addScan(const LaserScan& scan, const Pose2D& sensorPose);

  // The merged lines, sorted by orientation (and ID among equal orientations). Scan segments get
  // IDs 1, 2, 3, ... in the order extracted; a map line carries the smallest ID of its parts.
  const std::vector<LineSegment>& lines() const { return lines_; }
  std::size_t lineCount() const { return lines_.size(); }
  std::size_t scanCount() const { return scans_; }
  std::size_t pointCount() const { return points_; }        // valid scan points added
  std::size_t segmentCount() const { return nextId_ - 1; }  // scan segments extracted
  // Pairs (growing segment, map line) the grid offered for a merge test so far: the merge work.
  std::size_t mergeCandidateCount() const { return candidates_; }

 private:
  // The line sort key of lines().
  struct Key {
    double orientationRad;
    SegmentId id;
    friend auto operator<=>(const Key&, const Key&) = default;
  };
  Key key(LineGrid::Handle line) const { return {grid_.orientationRad(line), grid_.line(line).id}; }

  // Updates lines_ (and keys_): drops the lines with keys `gone`, adds those at `added` in grid_.
  void publish(std::vector<Key> gone, const std::vector<LineGrid::Handle>& added);

  LineExtractor extractor_;
  LineMerger merger_;
  LineGrid grid_;                   // the map lines, for merging
  std::vector<LineSegment> lines_;  // the same lines, sorted by key
  std::vector<Key> keys_;           // keys of lines_
  std::size_t scans_ = 0;
  std::size_t points_ = 0;
  std::size_t candidates_ = 0;
  SegmentId nextId_ = 1;
};

}  // namespace rgnav
