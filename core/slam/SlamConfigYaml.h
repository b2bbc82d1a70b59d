// The ScanMapper's parameters from YAML (config/modules/scanmapper.yaml): every key of SlamConfig
// (its describe() functions) required, no other key allowed, validated. Errors are ConfigErrors
// naming the file, the key path and the line.
#pragma once

#include <string>

#include "core/slam/SlamConfig.h"

namespace rgnav {

// `path` names the text in errors.
SlamConfig parseSlamConfig(const std::string& yamlText, const std::string& path);
// FileError if the file cannot be read.
SlamConfig loadSlamConfig(const std::string& file);

}  // namespace rgnav
