// GatewayDetectionClient: the gateway hypothesis buffer of the GatewayDetection module, by event
// ID, and its current gateways.
#pragma once

#include <vector>

#include "GatewayDetection.hh"
#include "clientlibs/common/ModuleClient.h"
#include "core/rgmap/feed/MappingInputs.h"

namespace rgnav {

// It is the kernel's event input (MappingInputs.h) in the kernel module.
class GatewayDetectionClient : public ModuleClientOf<RGNav::GatewayDetection>, public GatewayEventInput {
 public:
  explicit GatewayDetectionClient(ClientSettings settings = ClientSettings::fromEnvironment(),
                                  std::string objectName = "GatewayDetection");

  GatewayEventBatch eventsSince(GatewayEventId afterId, std::uint32_t maxCount) override;
  std::vector<GatewayRecord> gateways();
  GatewayRecord gateway(DetectorGatewayId id);
  DataId lastProcessedScan();
  bool detectsHallways();

 private:
  std::string consumer_;
};

}  // namespace rgnav
