// The Laser and Base servants (see SensorServants.h).
#include "servers/sensors/SensorServants.h"

#include "clientlibs/base/convert.h"
#include "clientlibs/common/convert.h"
#include "clientlibs/laser/convert.h"
#include "servers/common/WireChecks.h"

namespace rgnav {

namespace {
constexpr Raises kArgs = Raises::InvalidArgument;
constexpr Raises kLookup = Raises::InvalidArgument | Raises::NotAvailable;
}  // namespace

LaserImpl::LaserImpl(ServerRuntime& runtime, std::shared_ptr<LaserStream> stream, std::uint32_t maxBatch)
    : ServiceServant(runtime), stream_(std::move(stream)), maxBatch_(maxBatch) {}

RGNav::DataId LaserImpl::latestId() {
  return serve(Raises::FailedOnly, [&] { return stream_->latestScanId(); });
}

RGNav::DataId LaserImpl::oldestId() {
  return serve(Raises::FailedOnly, [&] { return stream_->oldestScanId(); });
}

RGNav::ScanBatch* LaserImpl::scansSince(RGNav::DataId afterId, CORBA::ULong maxCount, const char* consumer) {
  return serve(kArgs, [&] {
    const std::size_t count = wire::cappedCount(maxCount, maxBatch_, "maxCount");
    const auto batch = stream_->scansSince(afterId, count, wire::checkedName(consumer, "consumer"));
    runtime_.health().add("scans_served", batch.records.size());
    return new RGNav::ScanBatch(toIdl(batch));
  });
}

RGNav::LaserScan* LaserImpl::scan(RGNav::DataId id) {
  return serve(kLookup, [&] {
    wire::requireId(id, "id");
    return new RGNav::LaserScan(toIdl(stream_->scan(id)));
  });
}

BaseImpl::BaseImpl(ServerRuntime& runtime, std::shared_ptr<BaseStream> stream, std::uint32_t maxBatch)
    : ServiceServant(runtime), stream_(std::move(stream)), maxBatch_(maxBatch) {}

RGNav::DataId BaseImpl::latestOdometryId() {
  return serve(Raises::FailedOnly, [&] { return stream_->latestOdometryId(); });
}

RGNav::OdometryBatch* BaseImpl::odometrySince(RGNav::DataId afterId, CORBA::ULong maxCount, const char* consumer) {
  return serve(kArgs, [&] {
    const std::size_t count = wire::cappedCount(maxCount, maxBatch_, "maxCount");
    const auto batch = stream_->odometrySince(afterId, count, wire::checkedName(consumer, "consumer"));
    runtime_.health().add("odometry_served", batch.records.size());
    return new RGNav::OdometryBatch(toIdl(batch));
  });
}

RGNav::Odometry BaseImpl::odometryAt(const RGNav::Time& stamp) {
  return serve(kLookup, [&] {
    wire::requireValid(stamp, "stamp");
    return toIdl(stream_->odometryAt(fromIdl(stamp)));
  });
}

void BaseImpl::setVelocity(CORBA::Double translational, CORBA::Double rotational) {
  serve(kArgs | Raises::NotSupported, [&] {
    wire::requireFinite(translational, "translational");
    wire::requireFinite(rotational, "rotational");
    stream_->setVelocity(translational, rotational);
  });
}

}  // namespace rgnav
