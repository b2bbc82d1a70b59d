// Test helpers: bounded waits for a condition (a process ending, a line in a file). They fail
// the test after a generous limit instead of hanging; no test asserts on how long they took.
#pragma once

#include <cppunit/extensions/HelperMacros.h>

#include <chrono>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>

#include "watchdog/ChildProcess.h"

namespace rgnav::testing {

constexpr std::chrono::seconds kWaitLimit{20};

// Polls `condition` every `period` until it holds; fails the test after `limit`. The condition
// may fail the test itself (a CppUnit assertion) to stop early.
inline void waitUntil(const std::function<bool()>& condition, const std::string& what,
                      std::chrono::milliseconds limit = kWaitLimit,
                      std::chrono::milliseconds period = std::chrono::milliseconds(5)) {
  const auto giveUp = std::chrono::steady_clock::now() + limit;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > giveUp) CPPUNIT_FAIL("timed out waiting for " + what);
    std::this_thread::sleep_for(period);
  }
}

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
