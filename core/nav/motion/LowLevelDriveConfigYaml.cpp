// Strict YAML reading of the LowLevelDrive module's parameters (see LowLevelDriveConfigYaml.h).
#include "core/nav/motion/LowLevelDriveConfigYaml.h"

#include "core/config/DescribedConfig.h"

namespace rgnav {

// describe() lists every field (LowLevelDriveConfigYaml.h): a field added to any of the structs
// stops the build here until it is listed there and in config/modules/lowleveldrive.yaml.
static_assert(sizeof(MotionLimits) == 6 * sizeof(double));
static_assert(sizeof(PostureGains) == 3 * sizeof(double));
// (LowLevelDriveConfig: three doubles and an int padded to a double's size.)
static_assert(sizeof(LowLevelDriveConfig) == 4 * sizeof(double) + sizeof(MotionLimits) + sizeof(PostureGains));

LowLevelDriveConfig parseLowLevelDriveConfig(const std::string& yamlText, const std::string& path) {
  // The drive's constructor validates limits, gains and periods (ConfigError naming the value).
  return parseChecked<LowLevelDriveConfig>(yamlText, path,
                                           [](const LowLevelDriveConfig& config) { LowLevelDrive{config}; });
}

LowLevelDriveConfig loadLowLevelDriveConfig(const std::string& file) {
  return parseLowLevelDriveConfig(readConfigFile(file), file);
}

}  // namespace rgnav
