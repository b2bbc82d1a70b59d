// Strict YAML reading of the PathPlanning module's parameters (see RoutePlannerConfigYaml.h).
#include "core/nav/planning/RoutePlannerConfigYaml.h"

#include "core/config/DescribedConfig.h"

namespace rgnav {

// describe() lists every field (RoutePlannerConfigYaml.h): a field added to either struct stops the
// build here until it is listed there and in config/modules/pathplanning.yaml.
static_assert(sizeof(FramedQuadtreePlannerConfig) == 2 * sizeof(double));
static_assert(sizeof(RoutePlannerConfig) == 8 * sizeof(double) + sizeof(FramedQuadtreePlannerConfig));

RoutePlannerConfig parseRoutePlannerConfig(const std::string& yamlText, const std::string& path) {
  return parseChecked<RoutePlannerConfig>(yamlText, path, [](const RoutePlannerConfig& config) { validate(config); });
}

RoutePlannerConfig loadRoutePlannerConfig(const std::string& file) {
  return parseRoutePlannerConfig(readConfigFile(file), file);
}

}  // namespace rgnav
