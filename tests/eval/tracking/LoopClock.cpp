// LoopClock: sleeping until fixed-grid deadlines and measuring the periods.
#include "tests/eval/tracking/LoopClock.h"

#include <thread>

namespace rgnav {

LoopClock::LoopClock(double periodSeconds, bool realTime)
    : period_(periodSeconds), realTime_(realTime), start_(Clock::now()) {}

double LoopClock::next() {
  ++ticks_;
  double now = ticks_ * period_;
  if (realTime_) {
    std::this_thread::sleep_until(start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(now)));
    now = std::chrono::duration<double>(Clock::now() - start_).count();
  }
  const double elapsed = now - now_;
  now_ = now;
  periods_.push_back(elapsed);
  return elapsed;
}

}  // namespace rgnav
