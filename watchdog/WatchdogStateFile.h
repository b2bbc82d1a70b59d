// The watchdog's state file: which module runs as which process (PID + start time), so that a
// restarted watchdog adopts modules that are still alive instead of restarting them. Writes
// are atomic: a reader sees the old file or the new one, never a partial one.
#pragma once

#include <string>
#include <vector>

#include "core/supervision/ProcessRecord.h"

namespace rgnav {

class WatchdogStateFile {
 public:
  explicit WatchdogStateFile(std::string path);

  const std::string& path() const { return path_; }
  // Replaces <path> atomically (writeFileAtomically). Throws FileError (the old file stays
  // intact), InvalidArgumentError for a module name that is empty or contains whitespace.
  void write(const std::vector<ProcessRecord>& records) const;
  // Empty if the file does not exist; FileError if it cannot be read, FormatError (with the
  // line) if it is not a state file.
  std::vector<ProcessRecord> read() const;

 private:
  std::string path_;
};

}  // namespace rgnav
