// CarmenLogReader: line loop, ID numbering and statistics around CarmenLineParser.
#include "core/logs/CarmenLogReader.h"

#include "core/common/Errors.h"

namespace rgnav {

namespace {

// Checks the options before any member uses them.
const LogReaderOptions& checked(const LogReaderOptions& options) {
  validate(options);
  return options;
}

}  // namespace

CarmenLogReader::CarmenLogReader(const std::string& path, const LogReaderOptions& options)
    : lines_(path, checked(options).maxLineLength), parser_(options.maxRange) {}

std::optional<LineReader::Line> CarmenLogReader::nextLine() {
  try {
    return lines_.next();
  } catch (const FormatError& e) {
    stats_.addTruncation(e.what());
    throw;
  }
}

std::optional<LogRecord> CarmenLogReader::next() {
  while (const auto line = nextLine()) {
    ++stats_.lines;
    if (line->overLong) {
      stats_.addOverLong(lines_.path(), line->number, lines_.maxLineLength());
      continue;
    }
    CarmenLine parsed = parser_.parse(line->text, stats_);
    if (auto* scan = std::get_if<LaserScan>(&parsed)) {
      scan->id = nextScanId_++;
      ++stats_.scans;
      return std::move(*scan);
    }
    if (auto* reading = std::get_if<OdometryReading>(&parsed)) {
      reading->id = nextOdometryId_++;
      ++stats_.odometryReadings;
      return *reading;
    }
    if (const auto* bad = std::get_if<MalformedLine>(&parsed)) {
      stats_.addMalformed(lines_.path(), line->number, bad->reason);
    } else if (std::holds_alternative<UnknownLine>(parsed)) {
      ++stats_.unknownMessages;
    }
  }
  return std::nullopt;
}

}  // namespace rgnav
