// CarmenLogWriter: records a run as a CARMEN log that CarmenLogReader (and other CARMEN tools)
// read back: FLASER lines with the ranges, the laser pose as given by the scan's sensorPose (the
// true pose in the simulator), the odometry pose, the timestamps and the host; ODOM lines with
// the odometry pose and velocities (formats in data/laser/SOURCES.md). Numbers are written in a
// fixed, locale-independent format (ranges to the millimetre, poses, angles and times to 1e-6),
// so the same records give byte-identical files. A +inf range (no return) is written as the
// no-return value (default 81.91 m, what SICK scanners log); NaN (dropped) and -inf as "nan".
#pragma once

#include <ostream>
#include <string>

#include "core/common/SensorData.h"

namespace rgnav {

struct CarmenLogWriterOptions {
  std::string host = "rgnav-sim";  // the host field; no whitespace
  // Written for +inf ranges; CarmenLogReader reads ranges at or beyond its maximum range
  // (default 80 m) as no return.
  double noReturnRange = 81.91;
};

class CarmenLogWriter {
 public:
  // Throws InvalidArgumentError for an empty host or one with whitespace, or a non-positive
  // no-return range.
  explicit CarmenLogWriter(std::ostream& out, CarmenLogWriterOptions options = {});

  // One FLASER line, both timestamps = scan.stamp. Throws InvalidArgumentError if the scan does
  // not have FLASER geometry (180/181/360/361 beams or any count >= 2 spread over 180 degrees
  // from -90 degrees) or has a non-finite pose or stamp; FileError if the stream fails.
  void write(const LaserScan& scan);

  // One ODOM line, acceleration 0, both timestamps = reading.stamp. Throws InvalidArgumentError
  // for non-finite values, FileError if the stream fails.
  void write(const OdometryReading& reading);

 private:
  void finishLine(double stamp);

  std::ostream* out_;
  CarmenLogWriterOptions options_;
  std::string line_;
};

}  // namespace rgnav
