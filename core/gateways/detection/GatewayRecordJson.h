// GatewayRecordJson: a GatewayRecord as JSON, as the GatewayDetection module's checkpoints and
// the RG Mapping Kernel's checkpoints write it. Reading a malformed record throws FormatError
// (file "<checkpoint>").
#pragma once

#include <nlohmann/json.hpp>

#include "core/gateways/detection/GatewayRecord.h"

namespace rgnav {

nlohmann::json jsonGatewayRecord(const GatewayRecord& record);
GatewayRecord gatewayRecordFrom(const nlohmann::json& j);

}  // namespace rgnav
