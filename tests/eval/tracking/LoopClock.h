// LoopClock: the 20 Hz control loop's clock in the tracking evaluation. Real time: a thread that
// sleeps until the next period's deadline (deadlines on a fixed grid, so a late tick does not
// shift the later ones) and measures the real periods; the simulation then advances by each real
// period, so simulated time equals wall time. Fast: the simulated time advances by the nominal
// period without sleeping (the periods are then nominal). A real-time clock asks for the
// SCHED_FIFO policy for its thread, as a robot's control loop runs, so that other load on the
// machine does not delay its wake-ups; without the privilege it runs under the normal policy
// and says so (scheduling()).
#pragma once

#include <chrono>
#include <string>
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
  // "simulated", "wall-fifo" or "wall-normal".
  std::string scheduling() const;
  const std::vector<double>& periods() const { return periods_; }

 private:
  using Clock = std::chrono::steady_clock;
  double period_;
  bool realTime_;
  bool fifo_ = false;
  Clock::time_point start_;
  long ticks_ = 0;
  double now_ = 0.0;
  std::vector<double> periods_;
};

}  // namespace rgnav
