// Release logic of the log playback (see LogPlayback.h).
#include "core/playback/LogPlayback.h"

#include "core/common/OdometryInterpolation.h"

namespace rgnav {

namespace {
Timestamp stampOf(const LogRecord& record) {
  return std::visit([](const auto& r) { return r.stamp; }, record);
}
}  // namespace

// Whether one more record would push out of `buffer` a record an active consumer has not fetched.
template <class Record>
bool LogPlayback::wouldEvictUnread(const DataBuffer<Record>& buffer, const Cursors& cursors, double wallElapsed) {
  if (!buffer.full()) return false;
  for (const auto& [consumer, cursor] : cursors)
    if (wallElapsed - cursor.lastAsked < kConsumerIdleSeconds && buffer.oldestId() > cursor.fetched) return true;
  return false;
}

void LogPlayback::advance(Cursors& cursors, const std::string& consumer, DataId afterId, double wallElapsed) {
  std::erase_if(cursors, [&](const auto& entry) { return wallElapsed - entry.second.lastAsked >= kConsumerIdleSeconds; });
  if (consumer.empty()) return;
  if (!cursors.contains(consumer) && cursors.size() >= kMaxConsumers) return;
  Cursor& cursor = cursors[consumer];
  cursor = Cursor{std::max(cursor.fetched, afterId), wallElapsed};
}

std::size_t LogPlayback::scanConsumers() const {
  std::lock_guard lock(mutex_);
  return scanCursors_.size();
}

LogPlayback::LogPlayback(std::unique_ptr<LogSource> source, ReplayMode mode, std::size_t bufferCapacity)
    : source_(std::move(source)), scans_(bufferCapacity), odometry_(bufferCapacity) {
  pull();
  schedule_.emplace(mode, pending_ ? stampOf(*pending_) : 0.0);
}

void LogPlayback::pull() {
  try {
    pending_ = source_->next();
  } catch (const Error& e) {
    pending_.reset();
    readError_ = e.what();
  }
  if (!pending_) endOfData();
}

void LogPlayback::endOfData() {
  scans_.markEndOfData();
  odometry_.markEndOfData();
}

void LogPlayback::release(double wallElapsed, Want want, DataId wantedId) {
  const bool asFast = schedule_->mode().kind == ReplayMode::Kind::AsFastAsConsumed;
  while (pending_) {
    const bool isScan = std::holds_alternative<LaserScan>(*pending_);
    if (asFast) {
      const DataId held = want == Want::Scans ? scans_.latestId() : odometry_.latestId();
      if (held >= wantedId) break;
      if (isScan ? wouldEvictUnread(scans_, scanCursors_, wallElapsed)
                 : wouldEvictUnread(odometry_, odometryCursors_, wallElapsed))
        break;
    } else if (!schedule_->released(stampOf(*pending_), wallElapsed)) {
      break;
    }
    if (isScan)
      scans_.push(std::move(std::get<LaserScan>(*pending_)));
    else
      odometry_.push(std::move(std::get<OdometryReading>(*pending_)));
    pull();
  }
}

DataBatch<LaserScan> LogPlayback::scansSince(DataId afterId, std::size_t maxCount, double wallElapsed,
                                             const std::string& consumer) {
  std::lock_guard lock(mutex_);
  advance(scanCursors_, consumer, afterId, wallElapsed);
  release(wallElapsed, Want::Scans, afterId + maxCount);
  return scans_.since(afterId, maxCount);
}

DataBatch<OdometryReading> LogPlayback::odometrySince(DataId afterId, std::size_t maxCount, double wallElapsed,
                                                      const std::string& consumer) {
  std::lock_guard lock(mutex_);
  advance(odometryCursors_, consumer, afterId, wallElapsed);
  release(wallElapsed, Want::Odometry, afterId + maxCount);
  return odometry_.since(afterId, maxCount);
}

LaserScan LogPlayback::scan(DataId id, double wallElapsed) {
  std::lock_guard lock(mutex_);
  release(wallElapsed, Want::Scans, id);
  return scans_.get(id);
}

OdometryReading LogPlayback::odometryAt(Timestamp stamp, double wallElapsed) {
  std::lock_guard lock(mutex_);
  // As fast as consumed: read on until a reading at or after the stamp is held.
  for (;;) {
    const DataId before = odometry_.latestId();
    if (!odometry_.records().empty() && odometry_.records().back().stamp > stamp) break;
    release(wallElapsed, Want::Odometry, before + 1);
    if (odometry_.latestId() == before) break;
  }
  return interpolateOdometry(odometry_.records(), stamp);
}

DataId LogPlayback::latestScanId(double wallElapsed) {
  std::lock_guard lock(mutex_);
  release(wallElapsed, Want::Scans, scans_.latestId() + 1);
  return scans_.latestId();
}

DataId LogPlayback::latestOdometryId(double wallElapsed) {
  std::lock_guard lock(mutex_);
  release(wallElapsed, Want::Odometry, odometry_.latestId() + 1);
  return odometry_.latestId();
}

DataId LogPlayback::oldestScanId() const {
  std::lock_guard lock(mutex_);
  return scans_.oldestId();
}

LogStats LogPlayback::stats() const {
  std::lock_guard lock(mutex_);
  return source_->stats();
}

std::string LogPlayback::readError() const {
  std::lock_guard lock(mutex_);
  return readError_;
}

}  // namespace rgnav
