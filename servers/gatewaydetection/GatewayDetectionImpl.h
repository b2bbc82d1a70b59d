// GatewayDetectionImpl: the GatewayDetection.idl servant: convert in, service call, convert out.
#pragma once

#include "GatewayDetection.hh"
#include "servers/common/ServiceServant.h"
#include "servers/gatewaydetection/GatewayDetectionService.h"

namespace rgnav {

class GatewayDetectionImpl : public ServiceServant<POA_RGNav::GatewayDetection> {
 public:
  GatewayDetectionImpl(ServerRuntime& runtime, GatewayDetectionService& service, std::uint32_t maxBatch);

  RGNav::GatewayEventBatch* eventsSince(RGNav::GatewayEventId afterId, CORBA::ULong maxCount,
                                        const char* consumer) override;
  RGNav::GatewayInfoSeq* gateways() override;
  RGNav::GatewayInfo* gatewayById(RGNav::GatewayId id) override;
  RGNav::DataId lastProcessedScan() override;
  CORBA::Boolean detectsHallways() override;

 private:
  GatewayDetectionService& service_;
  std::uint32_t maxBatch_;
};

}  // namespace rgnav
