// Strict YAML reading of the PathPlanning module's parameters (see RoutePlannerConfigYaml.h).
#include "core/nav/planning/RoutePlannerConfigYaml.h"

#include "core/config/DescribedConfig.h"

namespace rgnav {

RoutePlannerConfig parseRoutePlannerConfig(const std::string& yamlText, const std::string& path) {
  return parseChecked<RoutePlannerConfig>(yamlText, path, [](const RoutePlannerConfig& config) { validate(config); });
}

RoutePlannerConfig loadRoutePlannerConfig(const std::string& file) {
  return parseRoutePlannerConfig(readConfigFile(file), file);
}

}  // namespace rgnav
