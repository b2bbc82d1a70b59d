// Reaping, signalling and stopping of one supervised process.
#include "watchdog/ChildProcess.h"

#include <signal.h>
#include <sys/wait.h>

#include <cerrno>
#include <system_error>
#include <thread>

#include "core/common/Errors.h"
#include "watchdog/ProcStat.h"
#include "watchdog/ProcessError.h"

namespace rgnav {
namespace {

constexpr std::chrono::milliseconds kStopPollPeriod{10};

ExitStatus decode(int status) {
  return WIFSIGNALED(status) ? ExitStatus::signaled(WTERMSIG(status)) : ExitStatus::exited(WEXITSTATUS(status));
}

}  // namespace

ChildProcess::ChildProcess(pid_t pid, std::uint64_t startTime, bool adopted)
    : pid_(pid), startTime_(startTime), adopted_(adopted) {
  // kill(-1) or kill(0) would hit every process or our own group.
  if (pid_ <= 1) throw InvalidArgumentError("process: invalid PID " + std::to_string(pid_));
}

ChildProcess ChildProcess::start(const SpawnSpec& spec) {
  const pid_t pid = spawnProcess(spec);
  try {
    // Our unreaped child cannot vanish from /proc: it stays at least a zombie until we wait for it.
    const std::optional<ProcStat> stat = readProcStat(pid);
    if (!stat) throw ProcessError("no /proc entry for new process " + std::to_string(pid));
    return ChildProcess(pid, stat->startTime, false);
  } catch (const Error&) {
    discardChild(pid);
    throw;
  }
}

std::optional<ChildProcess> ChildProcess::adopt(pid_t pid, std::uint64_t startTime) {
  if (pid <= 1 || !isProcessAlive(pid, startTime)) return std::nullopt;
  return ChildProcess(pid, startTime, true);
}

std::optional<ExitStatus> ChildProcess::poll(SupervisionClock::time_point now) {
  if (exit_) return exit_;
  int status = 0;
  pid_t r = 0;
  do {
    r = waitpid(pid_, &status, WNOHANG);
  } while (r < 0 && errno == EINTR);
  if (r == pid_) {
    exit_ = decode(status);
  } else if (r < 0 && errno == ECHILD) {
    // Not our child (adopted after a watchdog restart): judge by /proc, zombies count as dead.
    if (!isProcessAlive(pid_, startTime_)) exit_ = ExitStatus::lost();
  } else if (r < 0) {
    throw ProcessError("waitpid " + std::to_string(pid_) + ": " + std::system_category().message(errno));
  }
  if (!exit_ && killAt_ && !killSent_ && now >= *killAt_) {
    signalGroup(SIGKILL);
    killSent_ = true;
  }
  return exit_;
}

bool ChildProcess::stillOurs() const {
  // An unreaped child of ours keeps its PID; an adopted process must prove its identity.
  return !exit_ && (!adopted_ || isProcessAlive(pid_, startTime_));
}

bool ChildProcess::send(pid_t target, int sig) {
  if (!stillOurs()) return false;
  if (kill(target, sig) == 0) return true;
  if (errno == ESRCH) return false;
  throw ProcessError("kill(" + std::to_string(target) + ", " + std::to_string(sig) +
                     "): " + std::system_category().message(errno));
}

bool ChildProcess::signal(int sig) { return send(pid_, sig); }

bool ChildProcess::signalGroup(int sig) { return send(-pid_, sig); }

void ChildProcess::requestStop(SupervisionClock::time_point now, std::chrono::nanoseconds timeout) {
  if (exit_ || killAt_) return;
  killAt_ = now + timeout;
  signalGroup(SIGTERM);
  signalGroup(SIGCONT);
}

ExitStatus ChildProcess::stop(std::chrono::nanoseconds timeout) {
  if (exit_) return *exit_;
  const SupervisionClock::time_point begin = SupervisionClock::now();
  requestStop(begin, timeout);
  const SupervisionClock::time_point giveUp = *killAt_ + kKillGrace;
  for (SupervisionClock::time_point now = begin;; now = SupervisionClock::now()) {
    if (const std::optional<ExitStatus> status = poll(now)) return *status;
    if (now > giveUp) {
      throw ProcessError("process " + std::to_string(pid_) + " still alive " + std::to_string(kKillGrace.count()) +
                         " s after SIGKILL");
    }
    std::this_thread::sleep_for(kStopPollPeriod);
  }
}

}  // namespace rgnav
