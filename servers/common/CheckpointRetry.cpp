// The backoff, health and log of failed checkpoints (see CheckpointRetry.h).
#include "servers/common/CheckpointRetry.h"

#include <algorithm>
#include <iostream>

namespace rgnav {

namespace {
constexpr const char* kSource = "checkpoint";
}

CheckpointRetry::CheckpointRetry(ModuleHealth& health, std::chrono::milliseconds minDelay,
                                 std::chrono::milliseconds maxDelay, Clock clock)
    : health_(health), minDelay_(minDelay), maxDelay_(std::max(minDelay, maxDelay)), clock_(std::move(clock)) {}

bool CheckpointRetry::due() const { return !failing() || clock_() >= nextAttempt_; }

void CheckpointRetry::succeeded() {
  if (!failing()) return;
  std::cerr << "checkpoint written again after " << failures_ << " failed attempt" << (failures_ == 1 ? "" : "s")
            << std::endl;
  failures_ = 0;
  health_.clearError(kSource);
}

void CheckpointRetry::failed(const std::string& reason) {
  std::chrono::milliseconds delay = minDelay_;
  for (unsigned i = 0; i < failures_ && delay < maxDelay_; ++i) delay *= 2;
  delay = std::min(delay, maxDelay_);
  ++failures_;
  nextAttempt_ = clock_() + delay;
  health_.setDegraded(kSource, reason);
  health_.add("checkpoint_failures");
  std::cerr << "checkpoint failed (" << failures_ << " in a row), next attempt in "
            << std::chrono::duration<double>(delay).count() << " s: " << reason << std::endl;
}

}  // namespace rgnav
