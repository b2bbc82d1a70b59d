// LogSource: the interface every log reader offers (records in log order, running statistics),
// the record type it yields and the options the readers share.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <variant>

#include "core/common/SensorData.h"
#include "core/logs/LineReader.h"
#include "core/logs/LogStats.h"

namespace rgnav {

// More beams (or remission values) than this in one scan make it malformed.
inline constexpr std::size_t kMaxBeams = 100000;

using LogRecord = std::variant<LaserScan, OdometryReading>;

struct LogReaderOptions {
  // Beams at or beyond this (metres) mean "no return" where the log gives no maximum range
  // (FLASER, Intel JSON). SICK logs write 81.83 / 81.91 for no return.
  double maxRange = 80.0;
  // Longer lines are skipped and counted.
  std::size_t maxLineLength = LineReader::kDefaultMaxLineLength;
  // Intel JSON only: the optional corrected-pose companion of the raw-odometry file.
  std::string correctedPosesPath;
};

// Throws InvalidArgumentError if maxRange is not a positive finite number or maxLineLength is 0.
void validate(const LogReaderOptions& options);

class LogSource {
 public:
  virtual ~LogSource() = default;
  // The next record in log order, or nullopt at the end. Scans and odometry readings carry their
  // own ID sequences 1, 2, 3, ... Throws FormatError if the file cannot be read further.
  virtual std::optional<LogRecord> next() = 0;
  virtual const LogStats& stats() const = 0;
};

}  // namespace rgnav
