// The log playback as a data source for the Laser and Base servants (see PlaybackStreams.h).
#include "drivers/carmen/PlaybackStreams.h"

namespace rgnav {

PlaybackStreams::PlaybackStreams(std::unique_ptr<LogSource> source, ReplayMode mode, std::size_t bufferCapacity,
                                 PlaybackClock clock)
    : playback_(std::move(source), mode, bufferCapacity), clock_(std::move(clock)) {}

DataBatch<LaserScan> PlaybackStreams::scansSince(DataId afterId, std::size_t maxCount, const std::string& consumer) {
  return playback_.scansSince(afterId, maxCount, clock_.elapsed(), consumer);
}

LaserScan PlaybackStreams::scan(DataId id) { return playback_.scan(id, clock_.elapsed()); }

DataId PlaybackStreams::latestScanId() { return playback_.latestScanId(clock_.elapsed()); }

DataId PlaybackStreams::oldestScanId() { return playback_.oldestScanId(); }

DataBatch<OdometryReading> PlaybackStreams::odometrySince(DataId afterId, std::size_t maxCount,
                                                          const std::string& consumer) {
  return playback_.odometrySince(afterId, maxCount, clock_.elapsed(), consumer);
}

OdometryReading PlaybackStreams::odometryAt(Timestamp stamp) { return playback_.odometryAt(stamp, clock_.elapsed()); }

DataId PlaybackStreams::latestOdometryId() { return playback_.latestOdometryId(clock_.elapsed()); }

void PlaybackStreams::setVelocity(double, double) {
  throw NotSupportedError("a log playback cannot drive; velocity commands need the simulator or a robot");
}

void PlaybackStreams::report(ModuleHealth& health) const {
  const LogStats stats = playback_.stats();
  health.set("log_lines", stats.lines);
  health.set("log_scans", stats.scans);
  health.set("log_odometry", stats.odometryReadings);
  health.set("log_malformed_lines", stats.malformedLines);
  health.set("log_overlong_lines", stats.overLongLines);
  health.set("log_skipped_lines", stats.skippedLines());
  health.set("log_truncated", stats.truncated ? 1 : 0);
  health.set("ranges_dropped", stats.droppedRanges);
  health.set("ranges_no_return", stats.noReturnRanges);
  if (const std::string error = playback_.readError(); !error.empty())
    health.setError("log", error);
  else if (!stats.problems.empty())
    health.setError("log", stats.problems.back());
}

}  // namespace rgnav
