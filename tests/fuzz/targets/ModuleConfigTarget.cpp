// Fuzz target: the module parameter files (config/modules/) parsed strictly. The first byte picks
// the module (ScanMapper, GatewayDetection, RG Mapping Kernel, PathPlanning), the rest is the YAML text.
#include "core/common/Errors.h"
#include "core/gateways/detection/GatewayDetectorConfigYaml.h"
#include "core/nav/planning/RoutePlannerConfigYaml.h"
#include "core/rgmap/kernel/RgMappingKernelConfigYaml.h"
#include "core/slam/SlamConfigYaml.h"
#include "tests/fuzz/targets/FuzzInput.h"
#include "tests/fuzz/targets/FuzzTargets.h"

namespace rgnav::fuzz {

void fuzzModuleConfig(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return;
  const std::string text = fuzzText(data + 1, size - 1);
  try {
    switch (data[0] % 4) {
      case 0:
        parseSlamConfig(text, "scanmapper.yaml");
        break;
      case 1:
        parseGatewayDetectorConfig(text, "gatewaydetection.yaml");
        break;
      case 2:
        parseRgMappingKernelConfig(text, "rgmappingkernel.yaml");
        break;
      default:
        parseRoutePlannerConfig(text, "pathplanning.yaml");
    }
  } catch (const Error&) {
  }
}

}  // namespace rgnav::fuzz
