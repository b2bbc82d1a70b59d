// Hash-grid lookup of points on long lines; see StructureLines.h.
#include "tests/eval/objects/StructureLines.h"

#include <algorithm>
#include <cmath>

namespace rgnav {
namespace {

constexpr double kBucketM = 0.5;

double distanceToSegment(const LineSegment& s, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = s.end - s.start;
  const double t = std::clamp((p - s.start).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (s.start + t * d - p).norm();
}

}  // namespace

StructureLines::StructureLines(double maxDistanceM, double extensionM)
    : maxDistance_(maxDistanceM), extension_(extensionM), bucket_(kBucketM) {}

std::uint64_t StructureLines::key(std::int64_t cx, std::int64_t cy) const {
  return (std::uint64_t(cx) << 32) ^ (std::uint64_t(cy) & 0xffffffffULL);
}

void StructureLines::add(const LineSegment& line) {
  const std::size_t index = lines_.size();
  LineSegment extended = line;
  extended.start -= extension_ * line.direction();
  extended.end += extension_ * line.direction();
  lines_.push_back(extended);
  const Eigen::Vector2d lo = extended.start.cwiseMin(extended.end).array() - maxDistance_;
  const Eigen::Vector2d hi = extended.start.cwiseMax(extended.end).array() + maxDistance_;
  for (auto cx = std::int64_t(std::floor(lo.x() / bucket_)); cx <= std::int64_t(std::floor(hi.x() / bucket_)); ++cx)
    for (auto cy = std::int64_t(std::floor(lo.y() / bucket_)); cy <= std::int64_t(std::floor(hi.y() / bucket_)); ++cy)
      buckets_[key(cx, cy)].push_back(index);
}

bool StructureLines::onLine(const Eigen::Vector2d& p) const {
  const auto it =
      buckets_.find(key(std::int64_t(std::floor(p.x() / bucket_)), std::int64_t(std::floor(p.y() / bucket_))));
  if (it == buckets_.end()) return false;
  return std::any_of(it->second.begin(), it->second.end(),
                     [&](std::size_t i) { return distanceToSegment(lines_[i], p) <= maxDistance_; });
}

}  // namespace rgnav
