// The GatewayDetection.idl servant (see GatewayDetectionImpl.h).
#include "servers/gatewaydetection/GatewayDetectionImpl.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/gatewaydetection/convert.h"
#include "servers/common/WireChecks.h"

namespace rgnav {

GatewayDetectionImpl::GatewayDetectionImpl(ServerRuntime& runtime, GatewayDetectionService& service,
                                           std::uint32_t maxBatch)
    : ServiceServant(runtime), service_(service), maxBatch_(maxBatch) {}

RGNav::GatewayEventBatch* GatewayDetectionImpl::eventsSince(RGNav::GatewayEventId afterId, CORBA::ULong maxCount,
                                                            const char* consumer) {
  return serve(Raises::InvalidArgument, [&] {
    const std::size_t count = wire::cappedCount(maxCount, maxBatch_, "maxCount");
    wire::checkedName(consumer, "consumer");
    const GatewayEventBatch batch = service_.eventsSince(afterId, count);
    runtime_.health().add("events_served", batch.events.size());
    return new RGNav::GatewayEventBatch(toIdl(batch));
  });
}

RGNav::GatewayInfoSeq* GatewayDetectionImpl::gateways() {
  return serve(Raises::FailedOnly, [&] {
    return new RGNav::GatewayInfoSeq(
        toIdlSeq<RGNav::GatewayInfoSeq>(service_.gateways(), [](const GatewayRecord& g) { return toIdl(g); }));
  });
}

RGNav::GatewayInfo* GatewayDetectionImpl::gatewayById(RGNav::GatewayId id) {
  return serve(Raises::InvalidArgument | Raises::NotAvailable, [&] {
    wire::requireId(id, "id");
    return new RGNav::GatewayInfo(toIdl(service_.gateway(DetectorGatewayId(id))));
  });
}

RGNav::DataId GatewayDetectionImpl::lastProcessedScan() {
  return serve(Raises::FailedOnly, [&] { return service_.lastProcessedScan(); });
}

CORBA::Boolean GatewayDetectionImpl::detectsHallways() {
  return serve(Raises::FailedOnly, [&] { return service_.detectsHallways(); });
}

}  // namespace rgnav
