// LoopPeriods: the real periods of a control loop (the time between the starts of successive
// ticks, on the steady clock), kept for the last `window` ticks: the last one, the 99th
// percentile (nearest rank) and the most, for the module's status and health (issue "Motion":
// control period p99 <= 55 ms). Not thread-safe: its owner guards it.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace rgnav {

class LoopPeriods {
 public:
  static constexpr std::size_t kDefaultWindow = 1200;  // one minute at 20 Hz

  explicit LoopPeriods(std::size_t window = kDefaultWindow);

  // A tick started at `start`; the first gives no period.
  void tickStarted(std::chrono::steady_clock::time_point start);

  std::uint64_t periods() const { return count_; }  // periods recorded since the start
  double lastSeconds() const;                        // 0 before the second tick
  double p99Seconds() const;                         // over the window; 0 before the second tick

 private:
  std::size_t window_;
  std::vector<double> ring_;  // seconds, at most window_ of them
  std::size_t next_ = 0;      // where the next period goes once the ring is full
  std::uint64_t count_ = 0;
  double last_ = 0.0;
  std::optional<std::chrono::steady_clock::time_point> previous_;
};

}  // namespace rgnav
