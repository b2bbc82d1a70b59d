// Small per-beam facts of a laser scan (REP 117 ranges, see SensorData.h) that the passage
// detector needs beside the valid points of ScanPoints.h: a beam's bearing, and whether it got
// no return within the maximum range (the scan sees past everything along it).
#pragma once

#include <cmath>
#include <cstddef>

#include "core/common/SensorData.h"

namespace rgnav {

// Bearing of `beam` relative to the sensor heading, radians.
inline double bearingOf(const LaserScan& scan, std::size_t beam) {
  return scan.startAngle + double(beam) * scan.angleIncrement;
}

inline bool isNoReturn(const LaserScan& scan, std::size_t beam) {
  const double r = scan.ranges[beam];
  return std::isinf(r) || (scan.maxRange > 0.0 && r >= scan.maxRange);
}

}  // namespace rgnav
