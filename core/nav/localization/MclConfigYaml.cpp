// Strict YAML reading of the Localization module's parameters (see MclConfigYaml.h).
#include "core/nav/localization/MclConfigYaml.h"

#include "core/config/DescribedConfig.h"

namespace rgnav {

// describe() lists every field (MclConfigYaml.h): a field added to any of the structs stops the
// build here until it is listed there and in config/modules/localization.yaml.
static_assert(sizeof(BeamModelConfig) == 9 * sizeof(double));  // (overlapMinCells, beams: std::size_t)
static_assert(sizeof(MotionModelConfig) == 4 * sizeof(double));
static_assert(sizeof(KldConfig) == 6 * sizeof(double));  // (two std::size_t counts)
static_assert(sizeof(MclConfig) ==
              7 * sizeof(double) + sizeof(BeamModelConfig) + sizeof(MotionModelConfig) + sizeof(KldConfig));

MclConfig parseMclConfig(const std::string& yamlText, const std::string& path) {
  return parseChecked<MclConfig>(yamlText, path, [](const MclConfig& config) { validate(config); });
}

MclConfig loadMclConfig(const std::string& file) { return parseMclConfig(readConfigFile(file), file); }

}  // namespace rgnav
