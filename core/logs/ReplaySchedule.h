// ReplaySchedule: decides, without reading any clock, which log records are released to
// consumers during a replay. Real time scaled by k: a record stamped s is due once the wall time
// since the start reaches (s - firstStamp) / k. As fast as consumed: every record is due at once,
// and only a window of released-but-unconsumed records limits the pace.
#pragma once

#include <cstddef>

#include "core/common/SensorData.h"
#include "core/logs/ReplayMode.h"

namespace rgnav {

class ReplaySchedule {
 public:
  static constexpr std::size_t kDefaultWindow = 100;

  // `firstStamp`: stamp of the record replayed at wall time 0. `window` (AsFastAsConsumed):
  // how many released records may wait unconsumed. Throws InvalidArgumentError if the speed is
  // not a positive finite number or the window is 0.
  ReplaySchedule(ReplayMode mode, Timestamp firstStamp, std::size_t window = kDefaultWindow);

  // Wall seconds after the start at which a record stamped `stamp` is due; 0 for records stamped
  // before firstStamp and in AsFastAsConsumed mode.
  double releaseTime(Timestamp stamp) const;

  // Whether a record stamped `stamp` is due `wallElapsedSeconds` after the start.
  bool released(Timestamp stamp, double wallElapsedSeconds) const;

  // Whether one more record may be released when `releasedCount` records were released and
  // `consumedCount` of them consumed. Always true in real time: the log does not wait.
  bool withinWindow(std::size_t releasedCount, std::size_t consumedCount) const;

  const ReplayMode& mode() const { return mode_; }
  Timestamp firstStamp() const { return firstStamp_; }

 private:
  ReplayMode mode_;
  Timestamp firstStamp_;
  std::size_t window_;
};

}  // namespace rgnav
