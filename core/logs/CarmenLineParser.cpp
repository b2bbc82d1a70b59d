// CarmenLineParser: the field layouts of FLASER, ROBOTLASER1 and ODOM (data/laser/SOURCES.md).
#include "core/logs/CarmenLineParser.h"

#include <algorithm>
#include <array>

#include "core/logs/FlaserGeometry.h"
#include "core/logs/LogSource.h"
#include "core/logs/RangeSanitizer.h"

namespace rgnav {

namespace {

constexpr std::array<std::string_view, 6> kIgnoredTypes = {"PARAM", "NEFF",    "SYNC",
                                                           "TRUEPOS", "VERTEX2", "EDGE2"};
constexpr std::string_view kIgnoredPrefix = "RAWLASER";

bool isMessageType(std::string_view field) {
  return std::all_of(field.begin(), field.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
}

bool isIgnoredType(std::string_view type) {
  return type.starts_with(kIgnoredPrefix) ||
         std::find(kIgnoredTypes.begin(), kIgnoredTypes.end(), type) != kIgnoredTypes.end();
}

std::string fieldCountMismatch(std::size_t expected, std::size_t actual) {
  return "expected " + std::to_string(expected) + " fields, line has " + std::to_string(actual);
}

}  // namespace

CarmenLineParser::CarmenLineParser(double flaserMaxRange) : flaserMaxRange_(flaserMaxRange) {}

CarmenLine CarmenLineParser::parse(std::string_view line, LogStats& stats) {
  fields_.split(line);
  if (fields_.size() == 0 || fields_[0].starts_with('#')) {
    return IgnoredLine{};
  }
  const std::string_view type = fields_[0];
  if (type == "FLASER") {
    return parseFlaser(stats);
  }
  if (type == "ROBOTLASER1") {
    return parseRobotLaser(stats);
  }
  if (type == "ODOM") {
    return parseOdometry();
  }
  if (!isMessageType(type)) {
    return MalformedLine{"not a CARMEN message type: " + quoteField(type)};
  }
  return isIgnoredType(type) ? CarmenLine{IgnoredLine{}} : CarmenLine{UnknownLine{}};
}

MalformedLine CarmenLineParser::malformed(std::string_view type) const {
  return {std::string(type) + ": " + fields_.failure()};
}

// FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_ts host logger_ts
CarmenLine CarmenLineParser::parseFlaser(LogStats& stats) {
  const std::size_t n = fields_.count(1, "beam count", kMaxBeams);
  if (!fields_.failed() && n == 0) {
    fields_.fail("no beams");
  }
  if (!fields_.failed() && fields_.size() != n + 11) {
    fields_.fail(fieldCountMismatch(n + 11, fields_.size()));
  }
  if (fields_.failed()) {
    return malformed("FLASER");
  }
  LaserScan scan;
  fields_.numbers(2, n, "range", raw_);
  scan.sensorPose = fields_.pose(n + 2, "laser");
  scan.odometry = fields_.pose(n + 5, "odometry");
  fields_.number(n + 8, "ipc timestamp");
  scan.stamp = fields_.finite(n + 10, "logger timestamp");
  if (fields_.failed()) {
    return malformed("FLASER");
  }
  scan.startAngle = kFlaserStartAngle;
  scan.angleIncrement = flaserAngleIncrement(n);
  scan.maxRange = flaserMaxRange_;
  sanitizeRanges(raw_, scan.maxRange, scan.ranges, stats);
  return scan;
}

// ROBOTLASER1 type start_angle fov res maxrange accuracy remission_mode n r1..rn nrem rem1..remk
//   laser_x laser_y laser_th robot_x robot_y robot_th tv rv fwd side turn ipc_ts host logger_ts
CarmenLine CarmenLineParser::parseRobotLaser(LogStats& stats) {
  const std::size_t n = fields_.count(8, "beam count", kMaxBeams);
  const std::size_t remissions =
      fields_.failed() ? 0 : fields_.count(n + 9, "remission count", kMaxBeams);
  if (!fields_.failed() && n == 0) {
    fields_.fail("no beams");
  }
  if (!fields_.failed() && fields_.size() != n + remissions + 24) {
    fields_.fail(fieldCountMismatch(n + remissions + 24, fields_.size()));
  }
  if (fields_.failed()) {
    return malformed("ROBOTLASER1");
  }
  LaserScan scan;
  fields_.number(1, "laser type");
  scan.startAngle = fields_.finite(2, "start angle");
  fields_.finite(3, "field of view");
  scan.angleIncrement = fields_.finite(4, "angular resolution");
  scan.maxRange = fields_.finite(5, "maximum range");
  fields_.number(6, "accuracy");
  fields_.number(7, "remission mode");
  fields_.numbers(9, n, "range", raw_);
  const std::size_t b = n + remissions + 10;
  scan.sensorPose = fields_.pose(b, "laser");
  scan.odometry = fields_.pose(b + 3, "robot");
  for (std::size_t i = b + 6; i < b + 11; ++i) {
    fields_.number(i, "velocity");
  }
  fields_.number(b + 11, "ipc timestamp");
  scan.stamp = fields_.finite(b + 13, "logger timestamp");
  if (!fields_.failed() && scan.maxRange <= 0.0) {
    fields_.fail("maximum range must be positive");
  }
  if (fields_.failed()) {
    return malformed("ROBOTLASER1");
  }
  sanitizeRanges(raw_, scan.maxRange, scan.ranges, stats);
  return scan;
}

// ODOM x y theta tv rv accel ipc_ts host logger_ts
CarmenLine CarmenLineParser::parseOdometry() {
  if (fields_.size() != 10) {
    fields_.fail(fieldCountMismatch(10, fields_.size()));
    return malformed("ODOM");
  }
  OdometryReading reading;
  reading.pose = fields_.pose(1, "odometry");
  reading.translationalVelocity = fields_.finite(4, "translational velocity");
  reading.rotationalVelocity = fields_.finite(5, "rotational velocity");
  fields_.number(6, "acceleration");
  fields_.number(7, "ipc timestamp");
  reading.stamp = fields_.finite(9, "logger timestamp");
  if (fields_.failed()) {
    return malformed("ODOM");
  }
  return reading;
}

}  // namespace rgnav
