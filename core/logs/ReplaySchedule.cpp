// ReplaySchedule: the release rule of each replay mode.
#include "core/logs/ReplaySchedule.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

ReplaySchedule::ReplaySchedule(ReplayMode mode, Timestamp firstStamp, std::size_t window)
    : mode_(mode), firstStamp_(firstStamp), window_(window) {
  const bool badSpeed = !std::isfinite(mode.speed) || mode.speed <= 0.0;
  if (mode.kind == ReplayMode::Kind::RealTime && badSpeed) {
    throw InvalidArgumentError("replay speed must be a positive number, got " +
                               std::to_string(mode.speed));
  }
  if (window == 0) {
    throw InvalidArgumentError("replay window must hold at least one record");
  }
}

double ReplaySchedule::releaseTime(Timestamp stamp) const {
  if (mode_.kind == ReplayMode::Kind::AsFastAsConsumed) {
    return 0.0;
  }
  return std::max(0.0, (stamp - firstStamp_) / mode_.speed);
}

bool ReplaySchedule::released(Timestamp stamp, double wallElapsedSeconds) const {
  return wallElapsedSeconds >= releaseTime(stamp);
}

bool ReplaySchedule::withinWindow(std::size_t releasedCount, std::size_t consumedCount) const {
  if (mode_.kind == ReplayMode::Kind::RealTime) {
    return true;
  }
  return releasedCount < consumedCount + window_;
}

}  // namespace rgnav
