// The GatewayDetection.idl servant (see GatewayDetectionImpl.h).
#include "servers/gatewaydetection/GatewayDetectionImpl.h"

#include <algorithm>

#include "clientlibs/common/convert.h"
#include "clientlibs/gatewaydetection/convert.h"
#include "servers/common/IdlErrors.h"

namespace rgnav {

GatewayDetectionImpl::GatewayDetectionImpl(ServerRuntime& runtime, GatewayDetectionService& service,
                                           std::uint32_t maxBatch)
    : ServiceServant(runtime), service_(service), maxBatch_(maxBatch) {}

RGNav::GatewayEventBatch* GatewayDetectionImpl::eventsSince(RGNav::GatewayEventId afterId, CORBA::ULong maxCount,
                                                            const char*) {
  if (maxCount == 0) throw RGNav::InvalidArgument("maxCount must be at least 1");
  const GatewayEventBatch batch = service_.eventsSince(afterId, std::min<std::size_t>(maxCount, maxBatch_));
  runtime_.health().add("events_served", batch.events.size());
  return new RGNav::GatewayEventBatch(toIdl(batch));
}

RGNav::GatewayInfoSeq* GatewayDetectionImpl::gateways() {
  return new RGNav::GatewayInfoSeq(
      toIdlSeq<RGNav::GatewayInfoSeq>(service_.gateways(), [](const GatewayRecord& g) { return toIdl(g); }));
}

RGNav::GatewayInfo* GatewayDetectionImpl::gatewayById(RGNav::GatewayId id) {
  return new RGNav::GatewayInfo(toIdl(withIdlErrors([&] { return service_.gateway(id); })));
}

RGNav::DataId GatewayDetectionImpl::lastProcessedScan() { return service_.lastProcessedScan(); }

CORBA::Boolean GatewayDetectionImpl::detectsHallways() { return service_.detectsHallways(); }

}  // namespace rgnav
