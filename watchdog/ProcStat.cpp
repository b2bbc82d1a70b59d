// /proc/<pid>/stat parsing and the liveness test for adopted processes.
#include "watchdog/ProcStat.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <sstream>
#include <string>

#include "watchdog/ProcessError.h"

namespace rgnav {

std::string readProcFile(pid_t pid, const std::string& name) {
  const int fd = ::open(("/proc/" + std::to_string(pid) + "/" + name).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return {};
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) text.clear();  // gone while we read
    if (n <= 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return text;
}

std::optional<ProcStat> readProcStat(pid_t pid) {
  const std::string path = "/proc/" + std::to_string(pid) + "/stat";
  const std::string text = readProcFile(pid, "stat");
  if (text.empty()) return std::nullopt;  // no such process, or it went away while we read
  // Field 2 is "(comm)" and comm may contain spaces and ')': fields 3.. follow the last ')'.
  const std::size_t close = text.rfind(')');
  if (close == std::string::npos) throw ProcessError(path + ": no ')' after the command name");
  std::istringstream fields(text.substr(close + 1));
  ProcStat stat{};
  std::string skipped;
  fields >> stat.state >> skipped >> stat.group;
  for (int field = 6; field < 22; ++field) fields >> skipped;
  fields >> stat.startTime;
  if (!fields) throw ProcessError(path + ": too few fields");
  return stat;
}

bool isProcessAlive(pid_t pid, std::uint64_t startTime) {
  if (pid <= 0) return false;
  if (kill(pid, 0) != 0 && errno != EPERM) return false;
  const std::optional<ProcStat> stat = readProcStat(pid);
  return stat && stat->state != 'Z' && stat->state != 'X' && stat->startTime == startTime;
}

std::chrono::nanoseconds processAge(std::uint64_t startTime) {
  double uptime = 0;
  std::ifstream("/proc/uptime") >> uptime;
  const double started = static_cast<double>(startTime) / static_cast<double>(sysconf(_SC_CLK_TCK));
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::duration<double>(std::max(0.0, uptime - started)));
}

std::string describeProcessState(char state) {
  switch (state) {
    case 'R': return "running";
    case 'S': return "sleeping";
    case 'D': return "in uninterruptible sleep";
    case 'T': return "stopped (SIGSTOP or SIGTSTP)";
    case 't': return "stopped by a debugger";
    case 'Z': return "a zombie";
    case 'X': return "dead";
    default: return std::string("in state ") + state;
  }
}

}  // namespace rgnav
