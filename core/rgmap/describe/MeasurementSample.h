// MeasurementSample: a uniform random sample of at most `capacity` obstacle measurements inside a
// region (the hits of RegionBeams.h), in the region frame, kept by reservoir sampling (Vitter's
// algorithm R). The accuracy of the region's line map (thesis 2.1.1: "how well the metric
// description fits to the acquired sensor data") is measured on it, so that measure costs the
// same however many scans the region has (LineMapAccuracy.h).
// Deliberate choice: uniform over all scans of the region rather than the most recent points, so
// the measure describes the whole region and not only the last view. Deterministic: the random
// generator has a fixed seed.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <random>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/rgmap/describe/RegionBeams.h"

namespace rgnav {

class MeasurementSample {
 public:
  // Throws ConfigError for a zero capacity.
  explicit MeasurementSample(std::size_t capacity = 2048);

  void addBeams(const RegionBeams& beams);
  void add(const Eigen::Vector2d& point);
  // Combines with the sample of another region whose frame has the pose `otherInThis` here: each
  // sample contributes in proportion to the measurements it stands for.
  void mergeFrom(const MeasurementSample& other, const Pose2D& otherInThis);

  const std::vector<Eigen::Vector2d>& points() const { return points_; }
  std::uint64_t seen() const { return seen_; }  // measurements offered so far
  std::size_t capacity() const { return capacity_; }

 private:
  std::size_t capacity_;
  std::vector<Eigen::Vector2d> points_;
  std::uint64_t seen_ = 0;
  std::mt19937_64 random_;
};

}  // namespace rgnav
