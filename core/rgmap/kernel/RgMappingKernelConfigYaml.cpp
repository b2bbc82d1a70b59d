// Strict YAML reading of the RG Mapping Kernel module's parameters (see RgMappingKernelConfigYaml.h).
#include "core/rgmap/kernel/RgMappingKernelConfigYaml.h"

#include "core/config/DescribedConfig.h"

namespace rgnav {

RgMappingKernelConfig parseRgMappingKernelConfig(const std::string& yamlText, const std::string& path) {
  return parseChecked<RgMappingKernelConfig>(yamlText, path,
                                             [](const RgMappingKernelConfig& config) { RgMappingKernel{config}; });
}

RgMappingKernelConfig loadRgMappingKernelConfig(const std::string& file) {
  return parseRgMappingKernelConfig(readConfigFile(file), file);
}

}  // namespace rgnav
