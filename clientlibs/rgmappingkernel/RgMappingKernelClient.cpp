// RgMappingKernelClient calls through the retrying connection (see RgMappingKernelClient.h).
#include "clientlibs/rgmappingkernel/RgMappingKernelClient.h"

#include <algorithm>

#include "clientlibs/common/convert.h"
#include "clientlibs/gatewaydetection/convert.h"
#include "clientlibs/rgmappingkernel/convert.h"

namespace rgnav {

using Kernel = RGNav::RGMappingKernel_ptr;

namespace {

ClientSettings withExportTimeout(ClientSettings settings) {
  settings.callTimeout = std::max<std::chrono::milliseconds>(settings.callTimeout,
                                                             RgMappingKernelClient::kExportCallTimeout);
  return settings;
}

}  // namespace

RgMappingKernelClient::RgMappingKernelClient(ClientSettings settings, std::string objectName)
    : ModuleClientOf(objectName, settings),
      consumer_(settings.consumer),
      exports_(objectName, withExportTimeout(settings)),
      requestIds_([] {
        std::random_device entropy;
        return (std::uint64_t{entropy()} << 32) | entropy();
      }()) {}

RgMappingKernelClient::RequestId RgMappingKernelClient::newRequestId() {
  RequestId id = 0;
  while (id == 0) id = requestIds_();
  return id;
}

MapSummaryView RgMappingKernelClient::summary() {
  return connection_.call("summary", [](Kernel k) { return fromIdl(k->summary()); });
}

RegionView RgMappingKernelClient::currentRegion() {
  return connection_.call("currentRegion", [](Kernel k) {
    RGNav::RegionInfo_var r = k->currentRegion();
    return fromIdl(r.in());
  });
}

RegionView RgMappingKernelClient::region(RegionId id) {
  return connection_.call("regionById", [&](Kernel k) {
    RGNav::RegionInfo_var r = k->regionById(id.value());
    return fromIdl(r.in());
  });
}

std::vector<RegionSummaryView> RgMappingKernelClient::regions() {
  return connection_.call("regions", [](Kernel k) {
    RGNav::RegionSummarySeq_var all = k->regions();
    return fromIdlSeq<std::vector<RegionSummaryView>>(all.in(), [](const RGNav::RegionSummary& s) { return fromIdl(s); });
  });
}

std::vector<GatewayView> RgMappingKernelClient::gateways() {
  return connection_.call("gateways", [](Kernel k) {
    RGNav::RgGatewaySeq_var all = k->gateways();
    return fromIdlSeq<std::vector<GatewayView>>(all.in(), [](const RGNav::RgGateway& g) { return fromIdl(g); });
  });
}

GraphView RgMappingKernelClient::graph() {
  return connection_.call("graph", [](Kernel k) {
    RGNav::RgGraphInfo_var g = k->graph();
    return fromIdl(g.in());
  });
}

PathView RgMappingKernelClient::findPath(RegionId startRegion, const Eigen::Vector2d& start, RegionId goalRegion,
                                         const Eigen::Vector2d& goal) {
  return connection_.call("findPath", [&](Kernel k) {
    RGNav::RgPath_var p = k->findPath(startRegion.value(), toIdl(start), goalRegion.value(), toIdl(goal));
    return fromIdl(p.in());
  });
}

void RgMappingKernelClient::nameRegion(RegionId id, const std::string& name) {
  const RequestId request = newRequestId();
  connection_.call("nameRegion", [&](Kernel k) { k->nameRegion(request, id.value(), name.c_str()); });
}

RegionId RgMappingKernelClient::regionByName(const std::string& name) {
  return connection_.call("regionByName", [&](Kernel k) { return RegionId(k->regionByName(name.c_str())); });
}

void RgMappingKernelClient::nameObject(RegionId region, const Eigen::Vector2d& atInRegion, const std::string& name) {
  const RequestId request = newRequestId();
  connection_.call("nameObject", [&](Kernel k) { k->nameObject(request, region.value(), toIdl(atInRegion), name.c_str()); });
}

RgMappingKernel::NamedObject RgMappingKernelClient::objectByName(const std::string& name) {
  return connection_.call("objectByName", [&](Kernel k) { return fromIdl(k->objectByName(name.c_str())); });
}

RegionId RgMappingKernelClient::mergeRegions(RegionId a, RegionId b, bool force) {
  const RequestId request = newRequestId();
  return connection_.call("mergeRegions",
                          [&](Kernel k) { return RegionId(k->mergeRegions(request, a.value(), b.value(), force)); });
}

RegionId RgMappingKernelClient::unmergeRegions(RegionId merged) {
  const RequestId request = newRequestId();
  return connection_.call("unmergeRegions", [&](Kernel k) { return RegionId(k->unmergeRegions(request, merged.value())); });
}

void RgMappingKernelClient::reportDoorState(GatewayId door, bool traversable, std::uint64_t request) {
  const RequestId id = request != 0 ? request : newRequestId();
  connection_.call("reportDoorState", [&](Kernel k) { k->reportDoorState(id, door.value(), traversable); });
}

void RgMappingKernelClient::reportTraversal(GatewayId gateway, RegionId from, RegionId to, DataId scanId) {
  const RequestId request = newRequestId();
  connection_.call("reportTraversal",
                   [&](Kernel k) { k->reportTraversal(request, gateway.value(), from.value(), to.value(), scanId); });
}

RgMapEventBatch RgMappingKernelClient::eventsSince(RgMapEventId afterId, std::uint32_t maxCount) {
  return connection_.call("eventsSince", [&](Kernel k) {
    RGNav::RgMapEventBatch_var b = k->eventsSince(afterId, maxCount, consumer_.c_str());
    return fromIdl(b.in());
  });
}

std::string RgMappingKernelClient::exportMap(const std::string& directory, const std::string& name, bool occupancy) {
  return exports_.call("exportMap", [&](Kernel k) {
    CORBA::String_var files = k->exportMap(directory.c_str(), name.c_str(), occupancy);
    return std::string(files.in());
  });
}

}  // namespace rgnav
