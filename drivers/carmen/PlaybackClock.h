// PlaybackClock: the wall-clock origin of a replay, kept in the module's state directory so that
// a playback server restarted after a crash continues the replay where the log's clock stands
// instead of starting the log over (real-time modes; irrelevant when replaying as fast as
// consumed). An orderly stop discards it: the next start replays from the beginning.
#pragma once

#include <chrono>
#include <string>

namespace rgnav {

class PlaybackClock {
 public:
  // Loads the origin from stateDir/replay-origin if it was written for the same log and mode;
  // otherwise starts now and writes it (atomically). An empty stateDir keeps nothing.
  PlaybackClock(const std::string& stateDir, const std::string& logPath, const std::string& mode);

  // Wall seconds since the replay started.
  double elapsed() const;
  bool resumed() const { return resumed_; }
  // Forgets the stored origin (on an orderly stop).
  void discard() const;

 private:
  std::string file_;  // empty without a state directory
  std::chrono::system_clock::time_point origin_;
  bool resumed_ = false;
};

}  // namespace rgnav
