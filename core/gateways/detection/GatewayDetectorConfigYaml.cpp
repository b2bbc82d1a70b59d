// Strict YAML reading of the GatewayDetection module's parameters (see GatewayDetectorConfigYaml.h).
#include "core/gateways/detection/GatewayDetectorConfigYaml.h"

#include "core/config/DescribedConfig.h"

namespace rgnav {

GatewayDetectorConfig parseGatewayDetectorConfig(const std::string& yamlText, const std::string& path) {
  return parseChecked<GatewayDetectorConfig>(yamlText, path, [](const GatewayDetectorConfig& config) {
    GatewayDetector{config, std::nullopt};
    VlmObserver{config.hallways};
    validate(config.areas);
  });
}

GatewayDetectorConfig loadGatewayDetectorConfig(const std::string& file) {
  return parseGatewayDetectorConfig(readConfigFile(file), file);
}

}  // namespace rgnav
