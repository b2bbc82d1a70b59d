// The RGMappingKernel.idl servant (see RgMappingKernelImpl.h).
#include "servers/rgmappingkernel/RgMappingKernelImpl.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/gatewaydetection/convert.h"
#include "clientlibs/rgmappingkernel/convert.h"
#include "servers/common/WireChecks.h"

namespace rgnav {

namespace {
constexpr Raises kArgs = Raises::InvalidArgument;
constexpr Raises kLookup = Raises::InvalidArgument | Raises::NotAvailable;
}  // namespace

RgMappingKernelImpl::RgMappingKernelImpl(ServerRuntime& runtime, RgMappingKernelService& service,
                                         std::uint32_t maxBatch, ExportRoot exportRoot)
    : ServiceServant(runtime), service_(service), maxBatch_(maxBatch), exportRoot_(std::move(exportRoot)) {}

RGNav::RgMapSummary RgMappingKernelImpl::summary() {
  return serve(Raises::FailedOnly, [&] { return toIdl(service_.summary()); });
}

RGNav::RegionInfo* RgMappingKernelImpl::currentRegion() {
  return serve(Raises::NotAvailable, [&] { return new RGNav::RegionInfo(toIdl(service_.currentRegion())); });
}

RGNav::RegionInfo* RgMappingKernelImpl::regionById(RGNav::RegionId id) {
  return serve(kLookup, [&] {
    wire::requireId(id, "id");
    return new RGNav::RegionInfo(toIdl(service_.region(RegionId(id))));
  });
}

RGNav::RegionSummarySeq* RgMappingKernelImpl::regions() {
  return serve(Raises::FailedOnly, [&] {
    return new RGNav::RegionSummarySeq(
        toIdlSeq<RGNav::RegionSummarySeq>(service_.regions(), [](const RegionSummaryView& r) { return toIdl(r); }));
  });
}

RGNav::RgGatewaySeq* RgMappingKernelImpl::gateways() {
  return serve(Raises::FailedOnly, [&] {
    return new RGNav::RgGatewaySeq(
        toIdlSeq<RGNav::RgGatewaySeq>(service_.gateways(), [](const GatewayView& g) { return toIdl(g); }));
  });
}

RGNav::RgGraphInfo* RgMappingKernelImpl::graph() {
  return serve(Raises::FailedOnly, [&] { return new RGNav::RgGraphInfo(toIdl(service_.graph())); });
}

RGNav::RgPath* RgMappingKernelImpl::findPath(RGNav::RegionId startRegion, const RGNav::Point2D& start,
                                             RGNav::RegionId goalRegion, const RGNav::Point2D& goal) {
  return serve(kLookup, [&] {
    wire::requireId(startRegion, "startRegion");
    wire::requireFinite(start, "start");
    wire::requireId(goalRegion, "goalRegion");
    wire::requireFinite(goal, "goal");
    return new RGNav::RgPath(
        toIdl(service_.findPath(RgPlace{RegionId(startRegion), fromIdl(start)}, RgPlace{RegionId(goalRegion), fromIdl(goal)})));
  });
}

void RgMappingKernelImpl::nameRegion(RGNav::RequestId requestId, RGNav::RegionId id, const char* name) {
  serve(kArgs, [&] {
    wire::requireId(requestId, "requestId");
    wire::requireId(id, "id");
    service_.nameRegion(requestId, RegionId(id), wire::checkedName(name, "name"));
  });
}

RGNav::RegionId RgMappingKernelImpl::regionByName(const char* name) {
  return serve(kLookup, [&] { return service_.regionByName(wire::checkedName(name, "name", false)).value(); });
}

void RgMappingKernelImpl::nameObject(RGNav::RequestId requestId, RGNav::RegionId region,
                                     const RGNav::Point2D& atInRegion, const char* name) {
  serve(kArgs, [&] {
    wire::requireId(requestId, "requestId");
    wire::requireId(region, "region");
    wire::requireFinite(atInRegion, "atInRegion");
    service_.nameObject(requestId, RegionId(region), fromIdl(atInRegion), wire::checkedName(name, "name"));
  });
}

RGNav::NamedObject RgMappingKernelImpl::objectByName(const char* name) {
  return serve(kLookup, [&] { return toIdl(service_.objectByName(wire::checkedName(name, "name", false))); });
}

RGNav::RegionId RgMappingKernelImpl::mergeRegions(RGNav::RequestId requestId, RGNav::RegionId a, RGNav::RegionId b,
                                                  CORBA::Boolean force) {
  return serve(kArgs, [&] {
    wire::requireId(requestId, "requestId");
    wire::requireId(a, "a");
    wire::requireId(b, "b");
    return service_.mergeRegions(requestId, RegionId(a), RegionId(b), force).value();
  });
}

RGNav::RegionId RgMappingKernelImpl::unmergeRegions(RGNav::RequestId requestId, RGNav::RegionId merged) {
  return serve(kArgs, [&] {
    wire::requireId(requestId, "requestId");
    wire::requireId(merged, "merged");
    return service_.unmergeRegions(requestId, RegionId(merged)).value();
  });
}

void RgMappingKernelImpl::reportDoorState(RGNav::RequestId requestId, RGNav::GatewayId door,
                                          CORBA::Boolean traversable) {
  serve(kArgs, [&] {
    wire::requireId(requestId, "requestId");
    wire::requireId(door, "door");
    service_.reportDoorState(requestId, GatewayId(door), traversable);
  });
}

void RgMappingKernelImpl::reportTraversal(RGNav::RequestId requestId, RGNav::GatewayId gateway, RGNav::RegionId from,
                                          RGNav::RegionId to, RGNav::DataId scanId) {
  serve(kArgs, [&] {
    wire::requireId(requestId, "requestId");
    wire::requireId(gateway, "gateway");
    wire::requireId(from, "from");
    wire::requireId(to, "to");
    service_.reportTraversal(requestId, GatewayId(gateway), RegionId(from), RegionId(to), scanId);
  });
}

RGNav::RgMapEventBatch* RgMappingKernelImpl::eventsSince(RGNav::RgMapEventId afterId, CORBA::ULong maxCount,
                                                         const char* consumer) {
  return serve(kArgs, [&] {
    const std::size_t count = wire::cappedCount(maxCount, maxBatch_, "maxCount");
    wire::checkedName(consumer, "consumer");
    const RgMapEventBatch batch = service_.eventsSince(afterId, count);
    runtime_.health().add("events_served", batch.events.size());
    return new RGNav::RgMapEventBatch(toIdl(batch));
  });
}

char* RgMappingKernelImpl::exportMap(const char* directory, const char* name, CORBA::Boolean occupancy) {
  return serve(kLookup, [&] {
    requireFileName(name, "name");
    const std::string dir = exportRoot_.directoryFor(directory);
    const std::string files = writeMapExport(service_.exportData(occupancy), dir, name);
    return CORBA::string_dup(files.c_str());
  });
}

}  // namespace rgnav
