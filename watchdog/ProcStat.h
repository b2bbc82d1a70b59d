// Reads a process's state and start time from /proc/<pid>/stat, so that a PID can be
// re-identified after a watchdog restart (PIDs are reused; PID + start time is not).
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <optional>

namespace rgnav {

struct ProcStat {
  char state;              // field 3: R, S, D, T, Z, X, ...
  std::uint64_t startTime;  // field 22: clock ticks after boot
};

// nullopt if there is no such process. Throws ProcessError if the file cannot be parsed.
std::optional<ProcStat> readProcStat(pid_t pid);

// True if `pid` exists, is neither a zombie nor dead, and started at `startTime`.
bool isProcessAlive(pid_t pid, std::uint64_t startTime);

}  // namespace rgnav
