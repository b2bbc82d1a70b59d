// LoopClock: the 20 Hz control loop's clock in the tracking evaluation. Real time: a thread that
// sleeps until the next period's deadline (deadlines on a fixed grid, so a late tick does not
// shift the later ones) and measures the real periods; the simulation then advances by each real
// period, so simulated time equals wall time. Fast: the simulated time advances by the nominal
// period without sleeping (the periods are then nominal).
#pragma once

#include <chrono>
#include <vector>

namespace rgnav {

class LoopClock {
 public:
  LoopClock(double periodSeconds, bool realTime);

  // Waits for the next tick; returns the seconds since the previous one.
  double next();
  // Seconds since the clock was made (real) or the sum of the periods (fast).
  double now() const { return now_; }
  bool realTime() const { return realTime_; }
  const std::vector<double>& periods() const { return periods_; }

 private:
  using Clock = std::chrono::steady_clock;
  double period_;
  bool realTime_;
  Clock::time_point start_;
  long ticks_ = 0;
  double now_ = 0.0;
  std::vector<double> periods_;
};

}  // namespace rgnav
