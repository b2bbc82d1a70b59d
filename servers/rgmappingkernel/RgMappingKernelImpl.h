// RgMappingKernelImpl: the RGMappingKernel.idl servant: check and convert in, service call,
// convert out; exports go below the export root.
#pragma once

#include "RGMappingKernel.hh"
#include "servers/common/ServiceServant.h"
#include "servers/rgmappingkernel/ExportRoot.h"
#include "servers/rgmappingkernel/RgMappingKernelService.h"

namespace rgnav {

class RgMappingKernelImpl : public ServiceServant<POA_RGNav::RGMappingKernel> {
 public:
  RgMappingKernelImpl(ServerRuntime& runtime, RgMappingKernelService& service, std::uint32_t maxBatch,
                      ExportRoot exportRoot);

  RGNav::RgMapSummary summary() override;
  RGNav::RegionInfo* currentRegion() override;
  RGNav::RegionInfo* regionById(RGNav::RegionId id) override;
  RGNav::RegionSummarySeq* regions() override;
  RGNav::RgGatewaySeq* gateways() override;
  RGNav::RgGraphInfo* graph() override;
  RGNav::RgPath* findPath(RGNav::RegionId startRegion, const RGNav::Point2D& start, RGNav::RegionId goalRegion,
                          const RGNav::Point2D& goal) override;
  void nameRegion(RGNav::RequestId requestId, RGNav::RegionId id, const char* name) override;
  RGNav::RegionId regionByName(const char* name) override;
  void nameObject(RGNav::RequestId requestId, RGNav::RegionId region, const RGNav::Point2D& atInRegion,
                  const char* name) override;
  RGNav::NamedObject objectByName(const char* name) override;
  RGNav::RegionId mergeRegions(RGNav::RequestId requestId, RGNav::RegionId a, RGNav::RegionId b,
                               CORBA::Boolean force) override;
  RGNav::RegionId unmergeRegions(RGNav::RequestId requestId, RGNav::RegionId merged) override;
  void reportDoorState(RGNav::RequestId requestId, RGNav::GatewayId door, CORBA::Boolean traversable) override;
  void reportTraversal(RGNav::RequestId requestId, RGNav::GatewayId gateway, RGNav::RegionId from,
                       RGNav::RegionId to, RGNav::DataId scanId) override;
  RGNav::RgMapEventBatch* eventsSince(RGNav::RgMapEventId afterId, CORBA::ULong maxCount, const char* consumer) override;
  char* exportMap(const char* directory, const char* name, CORBA::Boolean occupancy) override;

 private:
  RgMappingKernelService& service_;
  std::uint32_t maxBatch_;
  ExportRoot exportRoot_;
};

}  // namespace rgnav
