// LogPlayback: replays a log (any LogSource) into the bounded scan and odometry buffers that a
// Laser and a Base server serve by ID. Records are released by a ReplaySchedule: in real time
// (scaled) by the wall time since the replay started, or, as fast as consumed, as far as the
// consumers ask. As fast as consumed, the slowest consumer paces the replay: a record is not
// released while it would push out of a full buffer a record that one of the stream's active
// named consumers (those who asked within the last kConsumerIdleSeconds) has not fetched yet,
// so a consumer that went away for good does not stall the replay, and one that restarts within
// that time finds its records still there. Anonymous consumers ("") hold nothing back. The
// consumers a stream remembers are bounded: an idle one is forgotten, and beyond kMaxConsumers
// active ones a new name asks as if anonymous (a caller inventing names cannot grow the table).
// Thread-safe: the Laser and Base servants share one playback.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "core/common/DataBuffer.h"
#include "core/logs/LogSource.h"
#include "core/logs/ReplaySchedule.h"

namespace rgnav {

class LogPlayback {
 public:
  static constexpr double kConsumerIdleSeconds = 5.0;
  static constexpr std::size_t kMaxConsumers = 32;  // named consumers remembered per stream

  // Reads the first record to anchor the schedule. Throws as the source does.
  LogPlayback(std::unique_ptr<LogSource> source, ReplayMode mode, std::size_t bufferCapacity);

  // Scans/readings with ID > afterId (at most maxCount) after releasing what is due at
  // wallElapsed seconds since the replay started.
  // `consumer` names the caller ("" for anonymous).
  DataBatch<LaserScan> scansSince(DataId afterId, std::size_t maxCount, double wallElapsed,
                                  const std::string& consumer = "");
  DataBatch<OdometryReading> odometrySince(DataId afterId, std::size_t maxCount, double wallElapsed,
                                           const std::string& consumer = "");
  LaserScan scan(DataId id, double wallElapsed);
  // Odometry interpolated at a stamp from the buffered readings; NotAvailableError outside them.
  OdometryReading odometryAt(Timestamp stamp, double wallElapsed);

  DataId latestScanId(double wallElapsed);
  DataId latestOdometryId(double wallElapsed);
  DataId oldestScanId() const;
  // Named consumers remembered for the scan stream.
  std::size_t scanConsumers() const;

  LogStats stats() const;
  // Why the replay ended early (a read error in the middle of the log), empty if it did not.
  std::string readError() const;

 private:
  enum class Want { Scans, Odometry };
  // Releases due records; in as-fast mode until the wanted buffer holds `wantedId`.
  void release(double wallElapsed, Want want, DataId wantedId);
  void pull();  // reads the next record into pending_ (or marks the end)
  void endOfData();

  // Per stream and named consumer: the highest "after ID" it asked with, and when it last asked.
  struct Cursor {
    DataId fetched = 0;
    double lastAsked = 0.0;
  };
  using Cursors = std::map<std::string, Cursor>;
  template <class Record>
  static bool wouldEvictUnread(const DataBuffer<Record>& buffer, const Cursors& cursors, double wallElapsed);
  static void advance(Cursors& cursors, const std::string& consumer, DataId afterId, double wallElapsed);

  mutable std::mutex mutex_;
  std::unique_ptr<LogSource> source_;
  std::optional<LogRecord> pending_;
  std::optional<ReplaySchedule> schedule_;
  DataBuffer<LaserScan> scans_;
  DataBuffer<OdometryReading> odometry_;
  Cursors scanCursors_;
  Cursors odometryCursors_;
  std::string readError_;
};

}  // namespace rgnav
