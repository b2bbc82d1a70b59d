// Bounded waits for a condition: the one way tests, the test cluster and the benchmarks wait for
// something to happen instead of sleeping a fixed time. pollUntil says whether the condition held
// before the limit; waitUntil fails the CppUnit test if it did not. No test asserts on how long a
// wait took: the limits are generous, for a machine shared with other work.
#pragma once

#include <cppunit/extensions/HelperMacros.h>

#include <chrono>
#include <functional>
#include <string>
#include <thread>

namespace rgnav::testing {

constexpr std::chrono::seconds kWaitLimit{20};

// Polls `condition` every `period` until it holds (true) or `limit` has passed (false).
inline bool pollUntil(const std::function<bool()>& condition, std::chrono::milliseconds limit,
                      std::chrono::milliseconds period = std::chrono::milliseconds(5)) {
  const auto giveUp = std::chrono::steady_clock::now() + limit;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > giveUp) return false;
    std::this_thread::sleep_for(period);
  }
  return true;
}

// Polls `condition` until it holds; fails the test after `limit`. The condition may fail the test
// itself (a CppUnit assertion) to stop early.
inline void waitUntil(const std::function<bool()>& condition, const std::string& what,
                      std::chrono::milliseconds limit = kWaitLimit,
                      std::chrono::milliseconds period = std::chrono::milliseconds(5)) {
  if (!pollUntil(condition, limit, period)) CPPUNIT_FAIL("timed out waiting for " + what);
}

}  // namespace rgnav::testing
