// CheckpointPacer: when a module whose state grows with its input checkpoints again. Writing the
// whole state after every batch costs time in proportion to all the input so far, so a long run
// costs time quadratic in its length (a server-set run of a 27 000-scan floor plan in lock-step,
// with batches of a few scans, spent most of its time writing checkpoints). A module that can
// replay its input by ID loses nothing by checkpointing less often: after a restart it goes on
// from the last checkpoint and produces the same outputs again under the same IDs.
#pragma once

#include <chrono>

namespace rgnav {

class CheckpointPacer {
 public:
  // Throws ConfigError for a negative or non-finite interval; 0 checkpoints every time.
  explicit CheckpointPacer(double intervalS);

  // Whether at least the interval has passed since the last checkpoint (true before the first).
  bool due() const;
  // A checkpoint was just written.
  void written();

 private:
  std::chrono::steady_clock::duration interval_;
  std::chrono::steady_clock::time_point last_{};
  bool any_ = false;
};

}  // namespace rgnav
