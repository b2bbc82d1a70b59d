// CarmenLogReader: streams the scans (FLASER, ROBOTLASER1) and odometry readings (ODOM) of a
// CARMEN log, plain, gzip or xz. Comments and the message types PARAM, NEFF, SYNC, TRUEPOS,
// RAWLASER*, VERTEX2, EDGE2 are read past; other types are counted as unknown; malformed and
// over-long lines are skipped, counted and reported as "file:line: what" in stats(), as is
// the line where damaged compressed data ends the log.
#pragma once

#include <optional>
#include <string>

#include "core/logs/CarmenLineParser.h"
#include "core/logs/LineReader.h"
#include "core/logs/LogSource.h"

namespace rgnav {

class CarmenLogReader : public LogSource {
 public:
  // Throws FileError if the file cannot be opened, InvalidArgumentError for bad options.
  explicit CarmenLogReader(const std::string& path, const LogReaderOptions& options = {});

  // Throws FormatError (path, line reached) if the compressed data is truncated or corrupt, after
  // recording it in stats() as truncated.
  std::optional<LogRecord> next() override;
  const LogStats& stats() const override { return stats_; }

 private:
  // The line reader's next line; a damaged compressed stream is recorded before it is rethrown.
  std::optional<LineReader::Line> nextLine();

  LineReader lines_;
  CarmenLineParser parser_;
  LogStats stats_;
  DataId nextScanId_ = 1;
  DataId nextOdometryId_ = 1;
};

}  // namespace rgnav
