// Test helper: kills a process started by a test (and its process group) at scope exit, also
// when an assertion failed, and reaps it if it is our child. It acts only while the PID still
// has the recorded start time, so a reused PID is never touched.
#pragma once

#include <signal.h>
#include <sys/wait.h>

#include <cstdint>

#include "watchdog/ProcStat.h"

namespace rgnav::testing {

class ProcessGuard {
 public:
  ProcessGuard(pid_t pid, std::uint64_t startTime) : pid_(pid), startTime_(startTime) {}
  ProcessGuard(const ProcessGuard&) = delete;
  ProcessGuard& operator=(const ProcessGuard&) = delete;
  ~ProcessGuard() {
    try {
      const std::optional<ProcStat> stat = readProcStat(pid_);
      if (pid_ <= 1 || !stat || stat->startTime != startTime_) return;
      kill(-pid_, SIGKILL);
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);  // ECHILD if it is not our child
    } catch (...) {
      // A destructor must not throw; the process was already gone.
    }
  }

 private:
  pid_t pid_;
  std::uint64_t startTime_;
};

}  // namespace rgnav::testing
