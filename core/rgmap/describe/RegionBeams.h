// regionBeams: the part of each laser beam that lies inside the current region, in the region
// frame (thesis 5.2: "only measurements inside the region are considered. That means, laser beams
// that cross a gateway are filtered out"). Ranges follow REP 117 (SensorData.h):
//   - NaN and ranges <= 0 are left out;
//   - a finite range below maxRange (when the scan gives one) is a measurement: the beam runs to
//     its endpoint, which is an obstacle (hit);
//   - +inf or a range >= maxRange is "no return": the beam is free up to noReturnFreeRangeM (or
//     maxRange if that is shorter) and has no obstacle at its end;
//   - a beam that crosses a gateway segment (touching counts) is cut at the first crossing: free
//     up to there, and its end is no obstacle (it lies behind the gateway or on it).
// Deliberate difference: the thesis filters crossing beams out entirely; we keep the stretch in
// front of the gateway, which the robot saw free, and drop only what lies behind it.
// The sensor is assumed to be inside the region.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"
#include "core/rgmap/describe/GatewaySegment.h"

namespace rgnav {

struct RegionBeam {
  Eigen::Vector2d end = Eigen::Vector2d::Zero();  // region frame
  bool hit = false;                               // end is an obstacle measured inside the region
};

struct RegionBeams {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // sensor position, region frame
  std::vector<RegionBeam> beams;                     // usable beams in beam order
};

// The beams of `scan` taken with the sensor at `sensorPose` (its aligned pose in the region
// frame), cut at `gateways`. Throws InvalidArgumentError for a non-finite pose, scan angle or
// gateway end, or a negative or non-finite noReturnFreeRangeM.
RegionBeams regionBeams(const LaserScan& scan, const Pose2D& sensorPose, std::span<const GatewaySegment> gateways,
                        double noReturnFreeRangeM);

}  // namespace rgnav
