// PlaybackStreams: a log playback as the Laser and Base servers' data source: the LogPlayback
// with its replay clock bound in. A playback cannot be driven: velocity commands are refused.
#pragma once

#include <memory>

#include "core/common/SensorStreams.h"
#include "core/playback/LogPlayback.h"
#include "drivers/carmen/PlaybackClock.h"
#include "servers/common/ModuleHealth.h"

namespace rgnav {

class PlaybackStreams : public LaserStream, public BaseStream {
 public:
  PlaybackStreams(std::unique_ptr<LogSource> source, ReplayMode mode, std::size_t bufferCapacity, PlaybackClock clock);

  DataBatch<LaserScan> scansSince(DataId afterId, std::size_t maxCount, const std::string& consumer) override;
  LaserScan scan(DataId id) override;
  DataId latestScanId() override;
  DataId oldestScanId() override;

  DataBatch<OdometryReading> odometrySince(DataId afterId, std::size_t maxCount, const std::string& consumer) override;
  OdometryReading odometryAt(Timestamp stamp) override;
  DataId latestOdometryId() override;
  void setVelocity(double translational, double rotational) override;

  // Puts the reading statistics and problems into the module's status.
  void report(ModuleHealth& health) const;
  const PlaybackClock& clock() const { return clock_; }

 private:
  LogPlayback playback_;
  PlaybackClock clock_;
};

}  // namespace rgnav
