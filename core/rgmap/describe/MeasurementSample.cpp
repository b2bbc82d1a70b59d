// Reservoir sample of the measurements inside a region; see MeasurementSample.h.
#include "core/rgmap/describe/MeasurementSample.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/common/Errors.h"
#include "core/lines/ScanPoints.h"

namespace rgnav {

MeasurementSample::MeasurementSample(std::size_t capacity) : capacity_(capacity), random_(20240601u) {
  if (capacity_ == 0) throw ConfigError("measurement sample: capacity must be at least 1");
  points_.reserve(capacity_);
}

void MeasurementSample::addBeams(const RegionBeams& beams) {
  for (const RegionBeam& b : beams.beams)
    if (b.hit) add(b.end);
}

void MeasurementSample::add(const Eigen::Vector2d& point) {
  ++seen_;
  if (points_.size() < capacity_) {
    points_.push_back(point);
    return;
  }
  const std::uint64_t slot = std::uniform_int_distribution<std::uint64_t>(0, seen_ - 1)(random_);
  if (slot < capacity_) points_[slot] = point;
}

void MeasurementSample::mergeFrom(const MeasurementSample& other, const Pose2D& otherInThis) {
  const std::uint64_t total = seen_ + other.seen_;
  if (total == 0) return;
  const std::size_t keep = std::min(capacity_, points_.size() + other.points_.size());
  // Points from the other sample in proportion to what it stands for, within what each holds.
  const double wanted = std::round(double(keep) * double(other.seen_) / double(total));
  const std::size_t fromOther =
      std::clamp(std::size_t(wanted), keep - std::min(keep, points_.size()), other.points_.size());
  std::vector<Eigen::Vector2d> merged;
  merged.reserve(capacity_);
  std::sample(points_.begin(), points_.end(), std::back_inserter(merged), keep - fromOther, random_);
  std::vector<Eigen::Vector2d> theirs;
  std::sample(other.points_.begin(), other.points_.end(), std::back_inserter(theirs), fromOther, random_);
  for (const Eigen::Vector2d& p : theirs) merged.push_back(transformPoint(otherInThis, p));
  points_ = std::move(merged);
  seen_ = total;
}

}  // namespace rgnav
