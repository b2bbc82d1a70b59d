// Strict YAML reading of the ScanMapper's parameters (see SlamConfigYaml.h).
#include "core/slam/SlamConfigYaml.h"

#include "core/config/DescribedConfig.h"

namespace rgnav {

SlamConfig parseSlamConfig(const std::string& yamlText, const std::string& path) {
  return parseChecked<SlamConfig>(yamlText, path, [](const SlamConfig& config) { validate(config); });
}

SlamConfig loadSlamConfig(const std::string& file) { return parseSlamConfig(readConfigFile(file), file); }

}  // namespace rgnav
