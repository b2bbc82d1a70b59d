// LogCompleteness: whether the scans a map was built from were the whole log, read from the
// Laser module's status at the end of a build: a log playback counts the lines it skipped
// (log_skipped_lines) and whether the log ended early (log_truncated); other laser modules (the
// simulator, a robot) have no such counters and no log to be partial.
#pragma once

#include <string>

#include "clientlibs/common/ClientSettings.h"

namespace rgnav {

struct LogCompleteness {
  bool fromLog = false;  // the Laser module is a log playback
  bool whole = true;     // nothing skipped, not truncated
  std::string figures;   // "skipped_lines=N truncated=yes|no" for a log playback, else empty
  std::string problem;   // the Laser's last error when not whole ("file:line: what")
};

// Asks the Laser module of the set `settings` names. Throws Error naming the Laser
// module and the cause if it cannot.
LogCompleteness laserLogCompleteness(ClientSettings settings);

}  // namespace rgnav
