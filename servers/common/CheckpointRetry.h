// CheckpointRetry: what a module does about a checkpoint it could not write (a read-only, full
// or deleted state directory). The failure is not silent: the module turns DEGRADED with the
// reason as its status()'s lastError ("checkpoint: <file>: cannot ..."), counts it (health
// "checkpoint_failures") and logs it with the time until the next attempt. That attempt waits a
// bounded exponential backoff (minDelay, doubled after each failure in a row, at most maxDelay),
// so a state directory that stays unwritable costs one attempt per backoff, not one per input
// batch. The first write that succeeds makes the module healthy again and logs that.
// Not thread-safe: the module calls it under the lock that guards its checkpoints.
#pragma once

#include <chrono>
#include <functional>
#include <string>

#include "servers/common/ModuleHealth.h"

namespace rgnav {

class CheckpointRetry {
 public:
  using Clock = std::function<std::chrono::steady_clock::time_point()>;
  static constexpr std::chrono::milliseconds kMinDelay{250}, kMaxDelay{8000};

  explicit CheckpointRetry(ModuleHealth& health, std::chrono::milliseconds minDelay = kMinDelay,
                           std::chrono::milliseconds maxDelay = kMaxDelay, Clock clock = std::chrono::steady_clock::now);

  // Whether the last attempt failed: a checkpoint is owed.
  bool failing() const { return failures_ > 0; }
  // Whether an attempt may be made now: always unless failing and the backoff has not passed.
  bool due() const;
  // When the backoff after the last failure ends (only meaningful while failing).
  std::chrono::steady_clock::time_point nextAttempt() const { return nextAttempt_; }

  void succeeded();
  void failed(const std::string& reason);

 private:
  ModuleHealth& health_;
  std::chrono::milliseconds minDelay_, maxDelay_;
  Clock clock_;
  unsigned failures_ = 0;  // in a row
  std::chrono::steady_clock::time_point nextAttempt_{};
};

}  // namespace rgnav
