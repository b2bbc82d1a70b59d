// The Laser and Base servants (see SensorServants.h).
#include "servers/sensors/SensorServants.h"

#include <algorithm>

#include "clientlibs/base/convert.h"
#include "clientlibs/common/convert.h"
#include "clientlibs/laser/convert.h"
#include "servers/common/IdlErrors.h"

namespace rgnav {

namespace {
std::size_t cappedCount(CORBA::ULong requested, std::uint32_t cap) {
  if (requested == 0) throw RGNav::InvalidArgument("maxCount must be at least 1");
  return std::min<std::size_t>(requested, cap);
}
}  // namespace

LaserImpl::LaserImpl(ServerRuntime& runtime, std::shared_ptr<LaserStream> stream, std::uint32_t maxBatch)
    : ServiceServant(runtime), stream_(std::move(stream)), maxBatch_(maxBatch) {}

RGNav::DataId LaserImpl::latestId() { return stream_->latestScanId(); }

RGNav::DataId LaserImpl::oldestId() { return stream_->oldestScanId(); }

RGNav::ScanBatch* LaserImpl::scansSince(RGNav::DataId afterId, CORBA::ULong maxCount, const char* consumer) {
  const std::size_t count = cappedCount(maxCount, maxBatch_);
  auto batch = withIdlErrors([&] { return stream_->scansSince(afterId, count, consumer); });
  runtime_.health().add("scans_served", batch.records.size());
  return new RGNav::ScanBatch(toIdl(batch));
}

RGNav::LaserScan* LaserImpl::scan(RGNav::DataId id) {
  return new RGNav::LaserScan(toIdl(withIdlErrors([&] { return stream_->scan(id); })));
}

BaseImpl::BaseImpl(ServerRuntime& runtime, std::shared_ptr<BaseStream> stream, std::uint32_t maxBatch)
    : ServiceServant(runtime), stream_(std::move(stream)), maxBatch_(maxBatch) {}

RGNav::DataId BaseImpl::latestOdometryId() { return stream_->latestOdometryId(); }

RGNav::OdometryBatch* BaseImpl::odometrySince(RGNav::DataId afterId, CORBA::ULong maxCount, const char* consumer) {
  const std::size_t count = cappedCount(maxCount, maxBatch_);
  auto batch = withIdlErrors([&] { return stream_->odometrySince(afterId, count, consumer); });
  runtime_.health().add("odometry_served", batch.records.size());
  return new RGNav::OdometryBatch(toIdl(batch));
}

RGNav::Odometry BaseImpl::odometryAt(const RGNav::Time& stamp) {
  return toIdl(withIdlErrors([&] { return stream_->odometryAt(fromIdl(stamp)); }));
}

void BaseImpl::setVelocity(CORBA::Double translational, CORBA::Double rotational) {
  withIdlErrors([&] { stream_->setVelocity(translational, rotational); });
}

}  // namespace rgnav
