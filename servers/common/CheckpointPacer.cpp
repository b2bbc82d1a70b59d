// When to checkpoint again (see CheckpointPacer.h).
#include "servers/common/CheckpointPacer.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/common/Errors.h"

namespace rgnav {

CheckpointPacer::CheckpointPacer(double intervalS, double maxShare, Clock clock)
    : maxShare_(maxShare), clock_(std::move(clock)) {
  if (!std::isfinite(intervalS) || intervalS < 0.0)
    throw ConfigError("checkpoint interval must be a finite number of seconds >= 0");
  if (!(maxShare > 0.0 && maxShare <= 1.0)) throw ConfigError("checkpoint time share must lie in (0, 1]");
  interval_ = std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(intervalS));
  wait_ = interval_;
}

bool CheckpointPacer::due() const { return !any_ || clock_() - last_ >= wait_; }

void CheckpointPacer::written(std::chrono::steady_clock::time_point began) {
  last_ = clock_();
  const std::chrono::duration<double> took = last_ - began;
  const auto rest = std::chrono::duration_cast<std::chrono::steady_clock::duration>(took * ((1.0 - maxShare_) / maxShare_));
  wait_ = std::max(interval_, rest);
  any_ = true;
}

}  // namespace rgnav
