// Strict YAML reading of the exploration parameters (see ExplorationConfigYaml.h).
#include "core/nav/exploration/ExplorationConfigYaml.h"

#include "core/config/DescribedConfig.h"

namespace rgnav {

// describe() lists every field (ExplorationConfigYaml.h): a field added to any of the structs stops
// the build here until it is listed there.
static_assert(sizeof(ExplorationGridConfig) == 2 * sizeof(double));
static_assert(sizeof(FrontierConfig) == 3 * sizeof(double));  // (minCells: std::size_t)
static_assert(sizeof(ExplorationConfig) ==
              sizeof(ExplorationGridConfig) + sizeof(FrontierConfig) + 3 * sizeof(double));  // (maxGoalFailures)

ExplorationConfig explorationConfigFromYaml(const ConfigNode& section) {
  ExplorationConfig config;
  readDescribed(section, config);
  try {
    validate(config);
  } catch (const Error& e) {
    section.fail(e.what());
  }
  return config;
}

ExplorationConfig parseExplorationConfig(const std::string& yamlText, const std::string& path) {
  return parseChecked<ExplorationConfig>(yamlText, path, [](const ExplorationConfig& config) { validate(config); });
}

ExplorationConfig loadExplorationConfig(const std::string& file) {
  return parseExplorationConfig(readConfigFile(file), file);
}

}  // namespace rgnav
