// CarmenLogWriter: field order of FLASER/ODOM, fixed-precision number formatting with to_chars.
#include "core/sim/motion/CarmenLogWriter.h"

#include <charconv>
#include <cmath>

#include "core/common/Errors.h"
#include "core/common/ValueChecks.h"
#include "core/logs/FlaserGeometry.h"

namespace rgnav {

namespace {

constexpr int kRangeDecimals = 3;
constexpr int kDecimals = 6;

void append(std::string& line, double value, int decimals) {
  char buffer[64];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value,
                                          std::chars_format::fixed, decimals);
  if (error != std::errc()) {
    throw InvalidArgumentError("CarmenLogWriter: number too large to write");
  }
  line += ' ';
  line.append(buffer, end);
}

void requireFinite(double value, const std::string& what) {
  requireFiniteArgument(value, "CarmenLogWriter: " + what);
}

void appendPose(std::string& line, const Pose2D& pose, const std::string& what) {
  requireFinite(pose.x, what);
  requireFinite(pose.y, what);
  requireFinite(pose.theta, what);
  append(line, pose.x, kDecimals);
  append(line, pose.y, kDecimals);
  append(line, pose.theta, kDecimals);
}

}  // namespace

CarmenLogWriter::CarmenLogWriter(std::ostream& out, CarmenLogWriterOptions options)
    : out_(&out), options_(std::move(options)) {
  if (options_.host.empty() || options_.host.find_first_of(" \t\r\n") != std::string::npos) {
    throw InvalidArgumentError("CarmenLogWriter: the host name must be one word");
  }
  if (!(std::isfinite(options_.noReturnRange) && options_.noReturnRange > 0.0)) {
    throw InvalidArgumentError("CarmenLogWriter: the no-return range must be positive and finite");
  }
}

void CarmenLogWriter::finishLine(double stamp) {
  requireFinite(stamp, "timestamp");
  append(line_, stamp, kDecimals);
  line_ += ' ';
  line_ += options_.host;
  append(line_, stamp, kDecimals);
  line_ += '\n';
  out_->write(line_.data(), static_cast<std::streamsize>(line_.size()));
  if (!*out_) {
    throw FileError("CarmenLogWriter: writing the log failed");
  }
}

// FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_ts host logger_ts
void CarmenLogWriter::write(const LaserScan& scan) {
  const std::size_t n = scan.ranges.size();
  if (n < 2 || std::abs(scan.startAngle - kFlaserStartAngle) > 1e-9 ||
      std::abs(scan.angleIncrement - flaserAngleIncrement(n)) > 1e-9) {
    throw InvalidArgumentError("CarmenLogWriter: FLASER needs beams over 180 degrees from -90 degrees; scan " +
                               std::to_string(scan.id) + " has " + std::to_string(n) + " beams");
  }
  line_ = "FLASER " + std::to_string(n);
  for (const float r : scan.ranges) {
    if (r == LaserScan::kNoReturn) {
      append(line_, options_.noReturnRange, kRangeDecimals);
    } else if (std::isfinite(r)) {
      append(line_, double(r), kRangeDecimals);
    } else {
      line_ += " nan";
    }
  }
  appendPose(line_, scan.sensorPose, "laser pose");
  appendPose(line_, scan.odometry, "odometry pose");
  finishLine(scan.stamp);
}

// ODOM x y theta tv rv accel ipc_ts host logger_ts
void CarmenLogWriter::write(const OdometryReading& reading) {
  line_ = "ODOM";
  appendPose(line_, reading.pose, "odometry pose");
  requireFinite(reading.translationalVelocity, "translational velocity");
  requireFinite(reading.rotationalVelocity, "rotational velocity");
  append(line_, reading.translationalVelocity, kDecimals);
  append(line_, reading.rotationalVelocity, kDecimals);
  append(line_, 0.0, kDecimals);
  finishLine(reading.stamp);
}

}  // namespace rgnav
