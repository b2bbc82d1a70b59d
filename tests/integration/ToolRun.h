// runTool: runs one of the project's command-line tools (rgnav-plan, rgnav-nav, ...) against a
// test's set until it ends, with its output in a log file, bounded in time (the tool is killed
// when the test fails meanwhile); its exit status and output (stdout and stderr).
#pragma once

#include <sys/wait.h>

#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/WaitUntil.h"
#include "tests/support/cluster/TestCluster.h"
#include "watchdog/Spawn.h"

namespace rgnav::testing {

inline std::pair<int, std::string> runTool(const std::string& tool, const std::vector<std::string>& args,
                                           const std::string& logFile) {
  SpawnSpec spec;
  spec.argv = {TestCluster::program(tool)};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.logFile = logFile;
  spec.parentDeathSignal = SIGKILL;
  const pid_t pid = spawnProcess(spec);
  int status = 0;
  try {
    waitUntil([&] { return ::waitpid(pid, &status, WNOHANG) != 0; }, tool + " to end", std::chrono::seconds(60),
              std::chrono::milliseconds(20));
  } catch (...) {
    discardChild(pid);
    throw;
  }
  std::ifstream log(logFile);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1,
          std::string(std::istreambuf_iterator<char>(log), std::istreambuf_iterator<char>())};
}

}  // namespace rgnav::testing
