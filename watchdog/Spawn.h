// Starts a command as a new process: fork + exec, stdin from /dev/null, stdout and stderr
// appended to a log file, in its own process group. An exec failure is reported to the caller.
#pragma once

#include <sys/types.h>

#include <map>
#include <string>
#include <vector>

namespace rgnav {

struct SpawnSpec {
  std::vector<std::string> argv;           // argv[0] is looked up in PATH if it has no '/'
  std::map<std::string, std::string> env;  // added to (or replacing) the watchdog's environment
  std::string cwd;                         // empty: the watchdog's working directory
  std::string logFile;                     // created if missing, always appended to
  int parentDeathSignal = 0;               // if set: sent to the child when the spawning thread dies
};

// Returns the PID; the process leads its own process group (pgid == pid). Throws
// InvalidArgumentError for an empty argv, FileError if the log file cannot be opened, and
// ProcessError (with the errno text) if fork, chdir or exec fails; a child that failed to exec
// has already been reaped.
pid_t spawnProcess(const SpawnSpec& spec);

// Abandons a child that was just spawned: SIGKILL, then waits for it, so nothing is left behind.
void discardChild(pid_t pid);

}  // namespace rgnav
