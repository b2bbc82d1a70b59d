// The GatewayDetection module's parameters from YAML (config/modules/gatewaydetection.yaml):
// every key of GatewayDetectorConfig (its describe() functions) required, no other key allowed,
// validated as the detector, the VLM observer and the hallway-area tracker validate them. Errors
// are ConfigErrors naming the file, the key path and the line.
#pragma once

#include <string>

#include "core/gateways/detection/GatewayDetector.h"

namespace rgnav {

// `path` names the text in errors.
GatewayDetectorConfig parseGatewayDetectorConfig(const std::string& yamlText, const std::string& path);
// FileError if the file cannot be read.
GatewayDetectorConfig loadGatewayDetectorConfig(const std::string& file);

}  // namespace rgnav
