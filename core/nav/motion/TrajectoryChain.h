// TrajectoryChain: consecutive trajectory segments (thesis 5.5.3) that join without a gap: each
// segment starts where the previous one ends (position within 1 mm, heading within 1e-3 rad).
// Arc length s runs over the whole chain from 0 to length().
#pragma once

#include <vector>

#include "core/nav/motion/TrajectorySegment.h"

namespace rgnav {

class TrajectoryChain {
 public:
  TrajectoryChain() = default;
  // Throws InvalidArgumentError for an invalid segment or one that does not join.
  explicit TrajectoryChain(std::vector<TrajectorySegment> segments);

  // Throws InvalidArgumentError as the constructor.
  void append(const TrajectorySegment& segment);

  bool empty() const { return segments_.empty(); }
  const std::vector<TrajectorySegment>& segments() const { return segments_; }
  double length() const { return length_; }
  Pose2D start() const;  // InvalidArgumentError on an empty chain (also end())
  Pose2D end() const;

  // At arc length s in [0, length()] (clamped); the segment that starts at s wins at a joint.
  Pose2D poseAt(double s) const;
  double curvatureAt(double s) const;
  double sharpnessAt(double s) const;

 private:
  std::size_t segmentAt(double s) const;  // index of the segment holding s

  std::vector<TrajectorySegment> segments_;
  std::vector<double> startS_;  // arc length at each segment's start
  double length_ = 0.0;
};

}  // namespace rgnav
