// RegionEvidence: what the description of one region is computed from, kept together so that each
// scan is clipped to the region once (RegionBeams.h): the freespace grid, the convex hull of the
// measurements inside the region and a bounded sample of them. The RG Mapping Kernel (thesis 2.2,
// 5.2) adds the aligned scans of the current region as they come, describes the region at any
// time (describeRegion, RegionDescription.h: the preliminary description while the robot is in
// the region, the final one when it has left) and merges regions found to be one (6.1.1).
#pragma once

#include <cstddef>
#include <span>

#include "core/rgmap/describe/MeasurementHull.h"
#include "core/rgmap/describe/MeasurementSample.h"
#include "core/rgmap/describe/RegionFreespace.h"

namespace rgnav {

struct RegionEvidenceConfig {
  FreespaceConfig freespace;
  std::size_t samplePoints = 2048;  // measurements kept for the accuracy measure
};

template <class V>
void describe(V& v, RegionEvidenceConfig& c) {
  v.section("freespace", c.freespace);
  v.field("sample_points", c.samplePoints);
}

class RegionEvidence {
 public:
  // Throws ConfigError for an invalid freespace config or samplePoints == 0.
  explicit RegionEvidence(const RegionEvidenceConfig& config = {});

  // Adds `scan` taken with the sensor at `sensorPose` (its aligned pose in the region frame);
  // `gateways` are the region's gateway lines in the region frame. A scan the freespace grid
  // leaves out (taken beyond its largest extent, RegionFreespace.h) adds nothing at all. Throws
  // InvalidArgumentError and changes nothing for invalid input.
  void addScan(const LaserScan& scan, const Pose2D& sensorPose, std::span<const GatewaySegment> gateways);
  // Adds everything known about `other`, whose frame has the pose `otherInThis` in this region's
  // frame. Throws InvalidArgumentError and changes nothing as RegionFreespace::mergeFrom does.
  void mergeFrom(const RegionEvidence& other, const Pose2D& otherInThis);

  const RegionFreespace& freespace() const { return freespace_; }
  const MeasurementHull& hull() const { return hull_; }
  const MeasurementSample& sample() const { return sample_; }

 private:
  RegionFreespace freespace_;
  MeasurementHull hull_;
  MeasurementSample sample_;
};

}  // namespace rgnav
