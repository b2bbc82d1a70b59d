// When to checkpoint again (see CheckpointPacer.h).
#include "servers/common/CheckpointPacer.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

CheckpointPacer::CheckpointPacer(double intervalS) {
  if (!std::isfinite(intervalS) || intervalS < 0.0)
    throw ConfigError("checkpoint interval must be a finite number of seconds >= 0");
  interval_ = std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(intervalS));
}

bool CheckpointPacer::due() const { return !any_ || std::chrono::steady_clock::now() - last_ >= interval_; }

void CheckpointPacer::written() {
  last_ = std::chrono::steady_clock::now();
  any_ = true;
}

}  // namespace rgnav
