// Sensor records that flow between modules: laser scans and odometry readings, each with a
// unique increasing ID, a timestamp and the odometry pose it was taken at (DESIGN.md, "Data by ID").
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "core/common/Pose2D.h"

namespace rgnav {

// IDs start at 1; 0 means "none" (e.g. "everything after ID 0" is everything).
using DataId = std::uint64_t;

// Seconds; absolute (Unix) or log-relative, as the source provides.
using Timestamp = double;

// Range conventions (as ROS REP 117): a finite value in [0, maxRange) is a measurement,
// +infinity means "no return within maxRange", NaN means "invalid, dropped" (the source gave
// NaN, infinity or a negative value).
struct LaserScan {
  static constexpr float kNoReturn = std::numeric_limits<float>::infinity();
  static constexpr float kInvalid = std::numeric_limits<float>::quiet_NaN();

  DataId id = 0;
  Timestamp stamp = 0.0;
  Pose2D odometry;     // raw odometry pose of the robot when the scan was taken
  Pose2D sensorPose;   // pose of the laser as the source gives it (for corrected logs: the corrected pose)
  double startAngle = 0.0;      // radians, angle of the first beam relative to the robot heading
  double angleIncrement = 0.0;  // radians between beams
  double maxRange = 0.0;        // metres
  std::vector<float> ranges;    // metres, see the range conventions above

  friend bool operator==(const LaserScan&, const LaserScan&) = default;
};

struct OdometryReading {
  DataId id = 0;
  Timestamp stamp = 0.0;
  Pose2D pose;
  double translationalVelocity = 0.0;  // m/s
  double rotationalVelocity = 0.0;     // rad/s

  friend bool operator==(const OdometryReading&, const OdometryReading&) = default;
};

}  // namespace rgnav
