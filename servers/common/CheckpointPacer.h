// CheckpointPacer: when a module whose state grows with its input checkpoints again. Writing the
// whole state after every batch costs time in proportion to all the input so far, so a long run
// costs time quadratic in its length (a server-set run of a 27 000-scan floor plan in lock-step,
// with batches of a few scans, spent most of its time writing checkpoints). A module that can
// replay its input by ID loses nothing by checkpointing less often: after a restart it goes on
// from the last checkpoint and produces the same outputs again under the same IDs.
// The next checkpoint is due after the interval, and no earlier than the last write took times
// (1 - maxShare) / maxShare: however large the state grows over a long run, writing it - under
// the module's lock, so that clients wait meanwhile - takes at most maxShare of the module's time.
#pragma once

#include <chrono>
#include <functional>

namespace rgnav {

class CheckpointPacer {
 public:
  using Clock = std::function<std::chrono::steady_clock::time_point()>;

  // Throws ConfigError for a negative or non-finite interval (0 checkpoints every time unless a
  // write took time) or a share outside (0, 1].
  explicit CheckpointPacer(double intervalS, double maxShare = 0.1, Clock clock = std::chrono::steady_clock::now);

  // Whether the next checkpoint is due (true before the first).
  bool due() const;
  // The time to pass to written() when a checkpoint write begins.
  std::chrono::steady_clock::time_point now() const { return clock_(); }
  // A checkpoint whose write began at `began` was just written.
  void written(std::chrono::steady_clock::time_point began);

 private:
  std::chrono::steady_clock::duration interval_;
  double maxShare_;
  Clock clock_;
  std::chrono::steady_clock::duration wait_{};  // after the last write, at least the interval
  std::chrono::steady_clock::time_point last_{};
  bool any_ = false;
};

}  // namespace rgnav
