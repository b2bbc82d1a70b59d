// ScanPoints: the valid returns of one laser scan as points in the frame of a given sensor pose
// (thesis 5.2: aligned scans are turned into line scans). Ranges follow REP 117 (see
// SensorData.h): NaN (invalid) and +inf (no return) are skipped, as are values outside
// (0, maxRange) when the scan gives a maximum range.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "core/common/Pose2D.h"
#include "core/common/SensorData.h"

namespace rgnav {

struct ScanPoint {
  Eigen::Vector2d position;  // in the frame sensorPose is given in
  double rangeM = 0.0;
  std::size_t beam = 0;  // index into LaserScan::ranges
};

// The valid points of `scan`, in beam order, placed with the sensor at `sensorPose`.
std::vector<ScanPoint> scanPoints(const LaserScan& scan, const Pose2D& sensorPose);

// `p` (given in the frame of `pose`) expressed in the frame `pose` is given in.
Eigen::Vector2d transformPoint(const Pose2D& pose, const Eigen::Vector2d& p);

}  // namespace rgnav
