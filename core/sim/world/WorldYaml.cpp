// Strict YAML reading helpers of the world loaders.
#include "core/sim/world/WorldYaml.h"

#include <filesystem>
#include <vector>

#include "core/raster/ImageFile.h"
#include "core/sim/world/FileBytes.h"

namespace rgnav {
namespace {

std::vector<double> readNumbers(const ConfigNode& node, std::size_t count) {
  const std::vector<ConfigNode> items = node.items();
  if (items.size() != count) node.fail("expected a list of " + std::to_string(count) + " numbers");
  std::vector<double> values;
  for (const ConfigNode& item : items) values.push_back(item.asDouble());
  return values;
}

}  // namespace

YAML::Node loadYamlDocument(const std::string& path) {
  const std::string text = readFileBytes(path);
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(path + ": line " + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
}

double readPositive(const ConfigNode& node) {
  const double value = node.asDouble();
  if (!(value > 0.0)) node.fail("must be positive");
  return value;
}

double readNonNegative(const ConfigNode& node) {
  const double value = node.asDouble();
  if (value < 0.0) node.fail("must not be negative");
  return value;
}

double readFraction(const ConfigNode& node) {
  const double value = node.asDouble();
  if (value < 0.0 || value > 1.0) node.fail("must lie in [0, 1]");
  return value;
}

WorldPoint readPoint(const ConfigNode& node) {
  const std::vector<double> xy = readNumbers(node, 2);
  return {xy[0], xy[1]};
}

Eigen::Vector3d readPoint3(const ConfigNode& node) {
  const std::vector<double> xyz = readNumbers(node, 3);
  return {xyz[0], xyz[1], xyz[2]};
}

cv::Mat readReferencedImage(const std::string& yamlPath, const ConfigNode& node) {
  const std::filesystem::path file(node.asString());
  if (file.empty()) node.fail("must not be empty");
  const std::string imagePath =
      file.is_absolute() ? file.string() : (std::filesystem::path(yamlPath).parent_path() / file).lexically_normal().string();
  try {
    return readGrayImage(imagePath);
  } catch (const FileError& e) {
    throw FileError(yamlPath + ": " + node.path() + ": " + e.what());
  }
}

}  // namespace rgnav
