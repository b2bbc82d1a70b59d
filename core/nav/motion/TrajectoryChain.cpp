// TrajectoryChain: the joint check and the lookup of the segment at an arc length.
#include "core/nav/motion/TrajectoryChain.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

constexpr double kJointPositionTolerance = 1e-3;  // m
constexpr double kJointHeadingTolerance = 1e-3;   // rad

}  // namespace

TrajectoryChain::TrajectoryChain(std::vector<TrajectorySegment> segments) {
  segments_.reserve(segments.size());
  for (const TrajectorySegment& segment : segments) append(segment);
}

void TrajectoryChain::append(const TrajectorySegment& segment) {
  validate(segment);
  if (!segments_.empty()) {
    const Pose2D end = segments_.back().end();
    const double gap = std::hypot(segment.start.x - end.x, segment.start.y - end.y);
    const double turn = std::abs(normalizeAngle(segment.start.theta - end.theta));
    if (gap > kJointPositionTolerance || turn > kJointHeadingTolerance) {
      throw InvalidArgumentError("trajectory chain: segment " + std::to_string(segments_.size()) +
                                 " does not join the previous one (gap " + std::to_string(gap) +
                                 " m, heading " + std::to_string(turn) + " rad)");
    }
  }
  startS_.push_back(length_);
  segments_.push_back(segment);
  length_ += segment.length;
}

Pose2D TrajectoryChain::start() const {
  if (empty()) throw InvalidArgumentError("trajectory chain: empty chain has no start");
  return segments_.front().start;
}

Pose2D TrajectoryChain::end() const {
  if (empty()) throw InvalidArgumentError("trajectory chain: empty chain has no end");
  return segments_.back().end();
}

std::size_t TrajectoryChain::segmentAt(double s) const {
  if (empty()) throw InvalidArgumentError("trajectory chain: empty chain has no poses");
  const auto after = std::upper_bound(startS_.begin(), startS_.end(), s);
  return after == startS_.begin() ? 0 : static_cast<std::size_t>(after - startS_.begin()) - 1;
}

Pose2D TrajectoryChain::poseAt(double s) const {
  const std::size_t i = segmentAt(s);
  return segments_[i].poseAt(s - startS_[i]);
}

double TrajectoryChain::curvatureAt(double s) const {
  const std::size_t i = segmentAt(s);
  return segments_[i].curvatureAt(std::clamp(s - startS_[i], 0.0, segments_[i].length));
}

double TrajectoryChain::sharpnessAt(double s) const { return segments_[segmentAt(s)].sharpness; }

}  // namespace rgnav
