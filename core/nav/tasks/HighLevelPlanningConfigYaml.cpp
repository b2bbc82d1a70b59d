// Strict YAML reading of the High-Level Planning module's parameters (see
// HighLevelPlanningConfigYaml.h).
#include "core/nav/tasks/HighLevelPlanningConfigYaml.h"

#include "core/config/DescribedConfig.h"

namespace rgnav {

// describe() lists every field (HighLevelPlanningConfigYaml.h): a field added to the struct stops the
// build here until it is listed there and in config/modules/highlevelplanning.yaml.
static_assert(sizeof(HighLevelPlanningConfig) == sizeof(double) + sizeof(ExplorationConfig) + sizeof(RoutePlannerConfig));

HighLevelPlanningConfig parseHighLevelPlanningConfig(const std::string& yamlText, const std::string& path) {
  return parseChecked<HighLevelPlanningConfig>(yamlText, path,
                                               [](const HighLevelPlanningConfig& config) { validate(config); });
}

HighLevelPlanningConfig loadHighLevelPlanningConfig(const std::string& file) {
  return parseHighLevelPlanningConfig(readConfigFile(file), file);
}

}  // namespace rgnav
