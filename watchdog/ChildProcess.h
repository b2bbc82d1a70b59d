// One supervised process, started by this watchdog or adopted from a previous one: nonblocking
// reaping, signals, and stop (SIGTERM to its process group, SIGKILL after a timeout). An exited
// process is never signalled again, and an adopted one only while its start time still matches,
// so a reused PID is never hit. Not thread-safe: one supervision thread owns each object.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <optional>

#include "core/supervision/ExitStatus.h"
#include "core/supervision/ModulePolicy.h"
#include "core/supervision/SupervisionClock.h"
#include "watchdog/Spawn.h"

namespace rgnav {

class ChildProcess {
 public:
  // fork + exec (see spawnProcess for the errors).
  static ChildProcess start(const SpawnSpec& spec);
  // A process left running by a previous watchdog; nullopt if it is gone or the PID was reused.
  static std::optional<ChildProcess> adopt(pid_t pid, std::uint64_t startTime);

  pid_t pid() const { return pid_; }
  std::uint64_t startTime() const { return startTime_; }
  bool adopted() const { return adopted_; }
  const std::optional<ExitStatus>& exitStatus() const { return exit_; }

  // Reaps without blocking and sends the SIGKILL of a pending stop once its deadline is reached.
  // Returns the exit status once the process has ended (an adopted process that is not our
  // child ends as ExitStatus::lost()).
  std::optional<ExitStatus> poll(SupervisionClock::time_point now);
  // Signal to the process or to its whole process group; false if it has already ended.
  bool signal(int sig);
  bool signalGroup(int sig);
  // SIGTERM (and SIGCONT, for a stopped process) to the group now; poll() sends SIGKILL at
  // now + timeout. A second request keeps the earlier deadline.
  void requestStop(SupervisionClock::time_point now, std::chrono::nanoseconds timeout);
  // requestStop, then waits until the process has ended. Throws ProcessError if it survives
  // SIGKILL for kKillGrace.
  ExitStatus stop(std::chrono::nanoseconds timeout);

 private:
  ChildProcess(pid_t pid, std::uint64_t startTime, bool adopted);
  bool stillOurs() const;
  bool send(pid_t target, int sig);

  pid_t pid_;
  std::uint64_t startTime_;
  bool adopted_;
  std::optional<ExitStatus> exit_;
  std::optional<SupervisionClock::time_point> killAt_;
  bool killSent_ = false;
};

}  // namespace rgnav
