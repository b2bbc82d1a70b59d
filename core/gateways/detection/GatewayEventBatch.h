// Plain C++ form of what GatewayDetection::eventsSince serves (GatewayDetection.idl): the events
// of the gateway hypothesis buffer by ID, with how far the module has got.
#pragma once

#include <vector>

#include "core/gateways/detection/GatewayRecord.h"

namespace rgnav {

struct GatewayEventBatch {
  std::vector<GatewayEvent> events;
  GatewayEventId latestId = 0;
  DataId lastScan = 0;
  bool endOfData = false;
};

}  // namespace rgnav
