// The control loop's real periods (see LoopPeriods.h).
#include "servers/lowleveldrive/LoopPeriods.h"

#include <algorithm>

#include "core/common/Errors.h"

namespace rgnav {

LoopPeriods::LoopPeriods(std::size_t window) : window_(window) {
  if (window_ == 0) throw InvalidArgumentError("LoopPeriods: the window holds at least one period");
  ring_.reserve(window_);
}

void LoopPeriods::tickStarted(std::chrono::steady_clock::time_point start) {
  if (previous_) {
    last_ = std::chrono::duration<double>(start - *previous_).count();
    if (ring_.size() < window_) {
      ring_.push_back(last_);
    } else {
      ring_[next_] = last_;
      next_ = (next_ + 1) % window_;
    }
    ++count_;
  }
  previous_ = start;
}

double LoopPeriods::lastSeconds() const { return last_; }

double LoopPeriods::p99Seconds() const {
  if (ring_.empty()) return 0.0;
  std::vector<double> sorted = ring_;
  const auto rank = sorted.begin() + static_cast<long>(0.99 * double(sorted.size() - 1) + 0.5);
  std::nth_element(sorted.begin(), rank, sorted.end());
  return *rank;
}

}  // namespace rgnav
