// The Laser and Base servants of the log playback server: thin IDL wrappers around one shared
// LogPlayback (convert in, core call, convert out).
#pragma once

#include <memory>

#include "Base.hh"
#include "Laser.hh"
#include "core/playback/LogPlayback.h"
#include "drivers/carmen/PlaybackClock.h"
#include "servers/common/ServiceServant.h"

namespace rgnav {

// What both servants share; the server caps every batch at maxBatch records.
struct PlaybackShared {
  PlaybackShared(std::unique_ptr<LogSource> source, ReplayMode mode, std::size_t bufferCapacity, PlaybackClock replayClock,
                 std::uint32_t maxBatchCount)
      : playback(std::move(source), mode, bufferCapacity), clock(replayClock), maxBatch(maxBatchCount) {}

  LogPlayback playback;
  PlaybackClock clock;
  std::uint32_t maxBatch;
};

// Puts the playback's reading statistics and problems into the module's status.
void reportPlayback(ModuleHealth& health, const LogPlayback& playback);

class PlaybackLaserImpl : public ServiceServant<POA_RGNav::Laser> {
 public:
  PlaybackLaserImpl(ServerRuntime& runtime, std::shared_ptr<PlaybackShared> shared);

  RGNav::DataId latestId() override;
  RGNav::DataId oldestId() override;
  RGNav::ScanBatch* scansSince(RGNav::DataId afterId, CORBA::ULong maxCount, const char* consumer) override;
  RGNav::LaserScan* scan(RGNav::DataId id) override;

 private:
  std::shared_ptr<PlaybackShared> shared_;
};

class PlaybackBaseImpl : public ServiceServant<POA_RGNav::Base> {
 public:
  PlaybackBaseImpl(ServerRuntime& runtime, std::shared_ptr<PlaybackShared> shared);

  RGNav::DataId latestOdometryId() override;
  RGNav::OdometryBatch* odometrySince(RGNav::DataId afterId, CORBA::ULong maxCount, const char* consumer) override;
  RGNav::Odometry odometryAt(const RGNav::Time& stamp) override;
  void setVelocity(CORBA::Double translational, CORBA::Double rotational) override;

 private:
  std::shared_ptr<PlaybackShared> shared_;
};

}  // namespace rgnav
