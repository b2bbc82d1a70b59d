// ModuleProcesses: what supervision needs from the operating system's processes, by module
// name: start one, take over one a previous watchdog left running, kill or stop its process
// group, and learn which ones ended. The watchdog implements it with fork/exec, waitpid and
// /proc (watchdog/SetProcesses.h); tests implement it with a table in memory.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "core/supervision/ExitStatus.h"
#include "core/supervision/ProcessRecord.h"
#include "core/supervision/SupervisionClock.h"

namespace rgnav {

struct ModuleExit {
  std::string module;
  pid_t pid;
  ExitStatus status;
};

class ModuleProcesses {
 public:
  virtual ~ModuleProcesses() = default;

  // Starts the module's process as the leader of its own process group and returns its PID.
  // Throws an Error (with the reason) if it cannot be started.
  virtual pid_t start(const std::string& module) = 0;
  // Takes over a process left running by a previous watchdog and returns how long it has run.
  // nullopt if no process with that PID runs, or the PID now belongs to a process with another
  // start time (a reused PID).
  virtual std::optional<std::chrono::nanoseconds> adopt(const ProcessRecord& record) = 0;
  // SIGKILL to the module's process group.
  virtual void kill(const std::string& module) = 0;
  // SIGTERM to the module's process group now; SIGKILL once `timeout` has passed (see reap).
  virtual void requestStop(const std::string& module, SupervisionClock::time_point now,
                           std::chrono::nanoseconds timeout) = 0;
  // The processes that ended since the last call; they leave the table. Also sends the SIGKILL
  // of a stop whose timeout has passed.
  virtual std::vector<ModuleExit> reap(SupervisionClock::time_point now) = 0;
};

}  // namespace rgnav
