// Test helpers: bounded waits for a watchdog condition (a process ending, a line in a file), on
// the project's one poll helper (tests/support/WaitUntil.h).
#pragma once

#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/WaitUntil.h"
#include "watchdog/ChildProcess.h"

namespace rgnav::testing {

inline std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void waitForText(const std::string& path, const std::string& text) {
  waitUntil([&] { return readFile(path).find(text) != std::string::npos; }, "\"" + text + "\" in " + path);
}

inline ExitStatus waitForExit(ChildProcess& process) {
  waitUntil([&] { return process.poll(SupervisionClock::now()).has_value(); },
            "process " + std::to_string(process.pid()) + " to end");
  return *process.exitStatus();
}

}  // namespace rgnav::testing
