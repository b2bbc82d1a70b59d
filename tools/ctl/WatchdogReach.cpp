// Whether a set's watchdog can answer, judged from /proc (see WatchdogReach.h).
#include "tools/ctl/WatchdogReach.h"

#include <fstream>

#include "watchdog/PortHolder.h"
#include "watchdog/ProcStat.h"

namespace rgnav {

std::optional<pid_t> recordedWatchdogPid(const SetConfig& set) {
  std::ifstream in(set.runDir + "/watchdog.pid");
  pid_t pid = 0;
  if (in >> pid && pid > 1) return pid;
  return std::nullopt;
}

WatchdogCheck checkWatchdog(const SetConfig& set, std::optional<pid_t> expectedPid) {
  const std::string where = set.host + ":" + std::to_string(set.watchdog.port);
  const std::optional<PortHolder> holder = findPortHolder({set.host, set.watchdog.port});
  if (!holder)
    return {WatchdogReach::NotListening, "set '" + set.name + "' is not up (no watchdog at " + where + ")"};
  if (!expectedPid) expectedPid = recordedWatchdogPid(set);
  if (holder->pid != 0 && holder->pid != expectedPid) {
    return {WatchdogReach::OtherHolder,
            "port " + std::to_string(set.watchdog.port) + " of set '" + set.name + "' (its watchdog, " + where +
                ") is held by pid " + std::to_string(holder->pid) + " (" + holder->command +
                "), not by this set's watchdog: another set uses the same ports; stop it or give this set other ports"};
  }
  const std::optional<ProcStat> stat = holder->pid ? readProcStat(holder->pid) : std::nullopt;
  if (stat && (stat->state == 'T' || stat->state == 't')) {
    const std::string pid = std::to_string(holder->pid);
    return {WatchdogReach::Stopped,
            "the watchdog of set '" + set.name + "' (pid " + pid + " at " + where + ") does not answer: it is " +
                describeProcessState(stat->state) + "; resume it with `kill -CONT " + pid +
                "`, or end it with `kill -9 " + pid + "` (its modules keep running; `rgctl down " + set.name +
                "` then stops them)"};
  }
  return {WatchdogReach::Answers, ""};
}

}  // namespace rgnav
