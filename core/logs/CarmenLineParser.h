// CarmenLineParser: turns one line of a CARMEN log into a laser scan (FLASER, ROBOTLASER1), an
// odometry reading (ODOM), or the reason the line yields nothing. Field counts are checked against
// the line before anything is allocated from them.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/common/SensorData.h"
#include "core/logs/Fields.h"
#include "core/logs/LogStats.h"

namespace rgnav {

struct IgnoredLine {};  // comment, blank line, or a message type read past on purpose
struct UnknownLine {};  // a message type this parser does not know
struct MalformedLine {
  std::string reason;
};

using CarmenLine =
    std::variant<IgnoredLine, UnknownLine, MalformedLine, LaserScan, OdometryReading>;

class CarmenLineParser {
 public:
  // `flaserMaxRange`: metres at or beyond which a FLASER beam means "no return".
  explicit CarmenLineParser(double flaserMaxRange);

  // Parses `line`. Records come with ID 0 (the reader numbers them). Dropped and no-return beams
  // are counted into `stats` for lines that parse.
  CarmenLine parse(std::string_view line, LogStats& stats);

 private:
  CarmenLine parseFlaser(LogStats& stats);
  CarmenLine parseRobotLaser(LogStats& stats);
  CarmenLine parseOdometry();
  MalformedLine malformed(std::string_view type) const;

  double flaserMaxRange_;
  Fields fields_;
  std::vector<double> raw_;
};

}  // namespace rgnav
