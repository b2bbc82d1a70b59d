// ManualClock: a steady clock the test sets, for code that takes its clock as a
// std::function returning a steady_clock time point (CheckpointPacer, CheckpointRetry). Copies
// share one time.
#pragma once

#include <chrono>
#include <functional>
#include <memory>

namespace rgnav::testing {

struct ManualClock {
  std::shared_ptr<std::chrono::steady_clock::time_point> now =
      std::make_shared<std::chrono::steady_clock::time_point>();
  std::function<std::chrono::steady_clock::time_point()> clock() const {
    return [t = now] { return *t; };
  }
  void advance(std::chrono::milliseconds d) const { *now += d; }
};

}  // namespace rgnav::testing
