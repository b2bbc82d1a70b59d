// LogEndReport: a log source passed through unchanged that, once the log ends or fails, writes
// what was read and skipped to the playback's log, once, in lines starting "playback: ": the
// figures (scans=… skipped_lines=… truncated=yes|no) and one line per kind of skip with its first
// file:line. `rgctl map` shows these lines; `rgctl logs LogPlayback` has them.
#pragma once

#include <memory>
#include <ostream>
#include <string>

#include "core/logs/LogSource.h"

namespace rgnav {

class LogEndReport : public LogSource {
 public:
  LogEndReport(std::unique_ptr<LogSource> source, std::string path, std::ostream& out);

  std::optional<LogRecord> next() override;
  const LogStats& stats() const override { return source_->stats(); }

 private:
  void report();

  std::unique_ptr<LogSource> source_;
  std::string path_;
  std::ostream& out_;
  bool reported_ = false;
};

}  // namespace rgnav
