// LogEndReport: the end-of-log summary of the playback (see LogEndReport.h).
#include "drivers/carmen/LogEndReport.h"

#include "core/common/Errors.h"

namespace rgnav {

LogEndReport::LogEndReport(std::unique_ptr<LogSource> source, std::string path, std::ostream& out)
    : source_(std::move(source)), path_(std::move(path)), out_(out) {}

std::optional<LogRecord> LogEndReport::next() {
  try {
    std::optional<LogRecord> record = source_->next();
    if (!record) report();
    return record;
  } catch (const Error&) {
    report();
    throw;
  }
}

void LogEndReport::report() {
  if (reported_) return;
  reported_ = true;
  const LogStats& s = source_->stats();
  out_ << "playback: end of " << path_ << ": lines=" << s.lines << " scans=" << s.scans
       << " odometry=" << s.odometryReadings << " " << skipFigures(s) << "\n";
  for (const std::string& line : describeSkips(s)) out_ << "playback: " << line << "\n";
  out_.flush();
}

}  // namespace rgnav
