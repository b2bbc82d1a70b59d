// LoopClock: sleeping until fixed-grid deadlines and measuring the periods.
#include "tests/eval/tracking/LoopClock.h"

#include <pthread.h>
#include <sched.h>

#include <thread>

namespace rgnav {

LoopClock::LoopClock(double periodSeconds, bool realTime) : period_(periodSeconds), realTime_(realTime) {
  if (realTime_) {
    sched_param param{};
    param.sched_priority = 10;
    fifo_ = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
  }
  start_ = Clock::now();
}

std::string LoopClock::scheduling() const {
  if (!realTime_) return "simulated";
  return fifo_ ? "wall-fifo" : "wall-normal";
}

double LoopClock::next() {
  ++ticks_;
  double now = ticks_ * period_;
  if (realTime_) {
    const auto deadline = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(now));
    std::this_thread::sleep_until(start_ + deadline);
    now = std::chrono::duration<double>(Clock::now() - start_).count();
  }
  const double elapsed = now - now_;
  now_ = now;
  periods_.push_back(elapsed);
  return elapsed;
}

}  // namespace rgnav
