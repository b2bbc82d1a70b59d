// Strict reading of the world loaders' YAML files (map_server maps, vector worlds) on top of
// ConfigNode: every ConfigError starts with the file path, then names the key path and line
// (DESIGN.md "Config": unknown keys are errors). Internal to rgnav_sim_world.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <utility>

#include "core/common/Errors.h"
#include "core/config/ConfigNode.h"
#include "core/raster/OccupancyGrid.h"

namespace rgnav {

// The parsed YAML document of `path`: FileError if unreadable, ConfigError for bad YAML.
YAML::Node loadYamlDocument(const std::string& path);

// Calls parse(root ConfigNode) on the document of `path`; ConfigErrors get the path prefixed.
template <typename Parse>
auto parseYamlFile(const std::string& path, Parse&& parse) {
  const ConfigVars noVariables;
  const YAML::Node document = loadYamlDocument(path);
  try {
    return std::forward<Parse>(parse)(ConfigNode(document, "", noVariables));
  } catch (const ConfigError& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

double readPositive(const ConfigNode& node);
double readNonNegative(const ConfigNode& node);
double readFraction(const ConfigNode& node);  // in [0, 1]
WorldPoint readPoint(const ConfigNode& node);         // [x, y]
Eigen::Vector3d readPoint3(const ConfigNode& node);   // [x, y, z]

// Loads the image a key names, relative to the YAML file's folder unless absolute. A missing
// image is a FileError naming the YAML file, the key and the image path.
cv::Mat readReferencedImage(const std::string& yamlPath, const ConfigNode& node);

}  // namespace rgnav
