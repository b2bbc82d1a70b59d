// Laser and Base servants of the log playback server (see PlaybackServants.h).
#include "drivers/carmen/PlaybackServants.h"

#include <algorithm>

#include "clientlibs/base/convert.h"
#include "clientlibs/common/convert.h"
#include "clientlibs/laser/convert.h"

namespace rgnav {

namespace {

std::size_t cappedCount(CORBA::ULong requested, std::uint32_t cap) {
  if (requested == 0) throw RGNav::InvalidArgument("maxCount must be at least 1");
  return std::min<std::size_t>(requested, cap);
}

// Runs a core call and maps its typed errors to the IDL exceptions.
template <class F>
auto guarded(F&& f) {
  try {
    return f();
  } catch (const InvalidArgumentError& e) {
    throw RGNav::InvalidArgument(e.what());
  } catch (const NotAvailableError& e) {
    throw RGNav::NotAvailable(e.what());
  }
}

}  // namespace

void reportPlayback(ModuleHealth& health, const LogPlayback& playback) {
  const LogStats stats = playback.stats();
  health.set("log_lines", stats.lines);
  health.set("log_scans", stats.scans);
  health.set("log_odometry", stats.odometryReadings);
  health.set("log_malformed_lines", stats.malformedLines);
  health.set("log_overlong_lines", stats.overLongLines);
  health.set("ranges_dropped", stats.droppedRanges);
  health.set("ranges_no_return", stats.noReturnRanges);
  if (const std::string error = playback.readError(); !error.empty())
    health.setError("log", error);
  else if (!stats.problems.empty())
    health.setError("log", stats.problems.back());
}

PlaybackLaserImpl::PlaybackLaserImpl(ServerRuntime& runtime, std::shared_ptr<PlaybackShared> shared)
    : ServiceServant(runtime), shared_(std::move(shared)) {}

RGNav::DataId PlaybackLaserImpl::latestId() { return shared_->playback.latestScanId(shared_->clock.elapsed()); }

RGNav::DataId PlaybackLaserImpl::oldestId() { return shared_->playback.oldestScanId(); }

RGNav::ScanBatch* PlaybackLaserImpl::scansSince(RGNav::DataId afterId, CORBA::ULong maxCount, const char* consumer) {
  const std::size_t count = cappedCount(maxCount, shared_->maxBatch);
  auto batch = guarded([&] { return shared_->playback.scansSince(afterId, count, shared_->clock.elapsed(), consumer); });
  runtime_.health().add("scans_served", batch.records.size());
  return new RGNav::ScanBatch(toIdl(batch));
}

RGNav::LaserScan* PlaybackLaserImpl::scan(RGNav::DataId id) {
  return new RGNav::LaserScan(toIdl(guarded([&] { return shared_->playback.scan(id, shared_->clock.elapsed()); })));
}

PlaybackBaseImpl::PlaybackBaseImpl(ServerRuntime& runtime, std::shared_ptr<PlaybackShared> shared)
    : ServiceServant(runtime), shared_(std::move(shared)) {}

RGNav::DataId PlaybackBaseImpl::latestOdometryId() {
  return shared_->playback.latestOdometryId(shared_->clock.elapsed());
}

RGNav::OdometryBatch* PlaybackBaseImpl::odometrySince(RGNav::DataId afterId, CORBA::ULong maxCount, const char* consumer) {
  const std::size_t count = cappedCount(maxCount, shared_->maxBatch);
  auto batch = guarded([&] { return shared_->playback.odometrySince(afterId, count, shared_->clock.elapsed(), consumer); });
  runtime_.health().add("odometry_served", batch.records.size());
  return new RGNav::OdometryBatch(toIdl(batch));
}

RGNav::Odometry PlaybackBaseImpl::odometryAt(const RGNav::Time& stamp) {
  return toIdl(guarded([&] { return shared_->playback.odometryAt(fromIdl(stamp), shared_->clock.elapsed()); }));
}

void PlaybackBaseImpl::setVelocity(CORBA::Double, CORBA::Double) {
  throw RGNav::NotSupported("a log playback cannot drive; velocity commands need the simulator or a robot");
}

}  // namespace rgnav
