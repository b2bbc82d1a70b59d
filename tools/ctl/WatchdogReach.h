// WatchdogReach: before rgnav-ctl calls a set's watchdog, it finds out from /proc, at once and
// without a remote call, whether that watchdog can answer at all: is its port held, by this set's
// watchdog (not by another set's process after a port clash), and is that process not stopped.
// Otherwise the remote call would wait for its whole retry budget and then say nothing useful.
#pragma once

#include <sys/types.h>

#include <optional>
#include <string>

#include "core/supervision/SetConfig.h"

namespace rgnav {

enum class WatchdogReach { Answers, NotListening, OtherHolder, Stopped };

struct WatchdogCheck {
  WatchdogReach reach = WatchdogReach::NotListening;
  std::string message;  // for all but Answers: what is wrong and what to do
};

// The PID run_dir/watchdog.pid names (written by the watchdog once it holds the set's lock).
std::optional<pid_t> recordedWatchdogPid(const SetConfig& set);

// `expectedPid`: the set's watchdog (nullopt: the one recordedWatchdogPid names, if any).
WatchdogCheck checkWatchdog(const SetConfig& set, std::optional<pid_t> expectedPid);

}  // namespace rgnav
