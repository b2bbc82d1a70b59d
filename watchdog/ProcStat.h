// Reads a process's state and start time from /proc/<pid>/stat, so that a PID can be
// re-identified after a watchdog restart (PIDs are reused; PID + start time is not).
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace rgnav {

struct ProcStat {
  char state;              // field 3: R, S, D, T, Z, X, ...
  pid_t group;              // field 5: process group
  std::uint64_t startTime;  // field 22: clock ticks after boot
};

// The whole content of a file of /proc/<pid>/; empty if the process is gone (also when it
// vanishes while the file is read: the read then fails with ESRCH).
std::string readProcFile(pid_t pid, const std::string& name);

// nullopt if there is no such process. Throws ProcessError if the file cannot be parsed.
std::optional<ProcStat> readProcStat(pid_t pid);

// True if `pid` exists, is neither a zombie nor dead, and started at `startTime`.
bool isProcessAlive(pid_t pid, std::uint64_t startTime);

// How long ago a process with this start time (field 22) started, from /proc/uptime.
std::chrono::nanoseconds processAge(std::uint64_t startTime);

// The state letter of /proc/<pid>/stat in words ("stopped (SIGSTOP)" for T, ...).
std::string describeProcessState(char state);

}  // namespace rgnav
