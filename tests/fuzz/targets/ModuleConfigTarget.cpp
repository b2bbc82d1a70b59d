// Fuzz target: the module parameter files (config/modules/) parsed strictly. The first byte picks
// the module (ScanMapper, GatewayDetection, RG Mapping Kernel, PathPlanning,
// LowLevelDrive), the rest is the YAML text.
#include "core/common/Errors.h"
#include "core/gateways/detection/GatewayDetectorConfigYaml.h"
#include "core/nav/motion/LowLevelDriveConfigYaml.h"
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
    switch (data[0] % 5) {
      case 0:
        parseSlamConfig(text, "scanmapper.yaml");
        break;
      case 1:
        parseGatewayDetectorConfig(text, "gatewaydetection.yaml");
        break;
      case 2:
        parseRgMappingKernelConfig(text, "rgmappingkernel.yaml");
        break;
      case 3:
        parseRoutePlannerConfig(text, "pathplanning.yaml");
        break;
      default:
        parseLowLevelDriveConfig(text, "lowleveldrive.yaml");
    }
  } catch (const Error&) {
  }
}

}  // namespace rgnav::fuzz
