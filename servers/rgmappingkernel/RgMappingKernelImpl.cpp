// The RGMappingKernel.idl servant (see RgMappingKernelImpl.h).
#include "servers/rgmappingkernel/RgMappingKernelImpl.h"

#include <algorithm>

#include "clientlibs/common/convert.h"
#include "clientlibs/gatewaydetection/convert.h"
#include "clientlibs/rgmappingkernel/convert.h"
#include "servers/common/IdlErrors.h"
#include "servers/rgmappingkernel/MapExport.h"

namespace rgnav {

RgMappingKernelImpl::RgMappingKernelImpl(ServerRuntime& runtime, RgMappingKernelService& service, std::uint32_t maxBatch)
    : ServiceServant(runtime), service_(service), maxBatch_(maxBatch) {}

RGNav::RgMapSummary RgMappingKernelImpl::summary() { return toIdl(service_.summary()); }

RGNav::RegionInfo* RgMappingKernelImpl::currentRegion() {
  return new RGNav::RegionInfo(toIdl(withIdlErrors([&] { return service_.currentRegion(); })));
}

RGNav::RegionInfo* RgMappingKernelImpl::regionById(RGNav::RegionId id) {
  return new RGNav::RegionInfo(toIdl(withIdlErrors([&] { return service_.region(id); })));
}

RGNav::RegionSummarySeq* RgMappingKernelImpl::regions() {
  return new RGNav::RegionSummarySeq(
      toIdlSeq<RGNav::RegionSummarySeq>(service_.regions(), [](const RegionSummaryView& r) { return toIdl(r); }));
}

RGNav::RgGatewaySeq* RgMappingKernelImpl::gateways() {
  return new RGNav::RgGatewaySeq(
      toIdlSeq<RGNav::RgGatewaySeq>(service_.gateways(), [](const GatewayView& g) { return toIdl(g); }));
}

RGNav::RgGraphInfo* RgMappingKernelImpl::graph() { return new RGNav::RgGraphInfo(toIdl(service_.graph())); }

RGNav::RgPath* RgMappingKernelImpl::findPath(RGNav::RegionId startRegion, const RGNav::Point2D& start,
                                             RGNav::RegionId goalRegion, const RGNav::Point2D& goal) {
  return new RGNav::RgPath(toIdl(withIdlErrors([&] {
    return service_.findPath(RgPlace{startRegion, fromIdl(start)}, RgPlace{goalRegion, fromIdl(goal)});
  })));
}

void RgMappingKernelImpl::nameRegion(RGNav::RegionId id, const char* name) {
  withIdlErrors([&] {
    service_.nameRegion(id, name);
    return 0;
  });
}

RGNav::RegionId RgMappingKernelImpl::regionByName(const char* name) {
  return withIdlErrors([&] { return service_.regionByName(name); });
}

void RgMappingKernelImpl::nameObject(RGNav::RegionId region, const RGNav::Point2D& atInRegion, const char* name) {
  withIdlErrors([&] {
    service_.nameObject(region, fromIdl(atInRegion), name);
    return 0;
  });
}

RGNav::NamedObject RgMappingKernelImpl::objectByName(const char* name) {
  return toIdl(withIdlErrors([&] { return service_.objectByName(name); }));
}

RGNav::RegionId RgMappingKernelImpl::mergeRegions(RGNav::RegionId a, RGNav::RegionId b) {
  return withIdlErrors([&] { return service_.mergeRegions(a, b); });
}

RGNav::RgMapEventBatch* RgMappingKernelImpl::eventsSince(RGNav::RgMapEventId afterId, CORBA::ULong maxCount,
                                                         const char*) {
  const RgMapEventBatch batch =
      withIdlErrors([&] { return service_.eventsSince(afterId, std::min<std::size_t>(maxCount, maxBatch_)); });
  runtime_.health().add("events_served", batch.events.size());
  return new RGNav::RgMapEventBatch(toIdl(batch));
}

char* RgMappingKernelImpl::exportMap(const char* directory, const char* name, CORBA::Boolean occupancy) {
  const std::string files = withIdlErrors([&] {
    return service_.withKernel([&](const RgMappingKernel& kernel) { return exportMapFiles(kernel, directory, name, occupancy); });
  });
  return CORBA::string_dup(files.c_str());
}

}  // namespace rgnav
