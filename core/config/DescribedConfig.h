// Strict YAML reading and complete YAML writing of any parameter struct that lists its fields in
// a describe() function beside it (found by argument-dependent lookup):
//   template <class V> void describe(V& v, ScanPointsConfig& c) {
//     v.field("max_range_m", c.maxRange);               // double, std::size_t, int or bool, as in the code
//     v.degrees("min_aperture_deg", c.minApertureRad);  // degrees in the file, radians in the code
//     v.section("grid", c.grid);                        // a nested struct with its own describe()
//   }
// Key names carry the unit (DESIGN.md: SI in the code, converted at the config edge).
// Reading (parseDescribed): every listed key is required, any other key is an error, numbers must
// be finite and counts non-negative integers; each error is a ConfigError naming the file, the key
// path and the line. Writing (describedYaml): every key in the listed order, each number with the
// fewest digits that read back to exactly the same double.
#pragma once

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/Errors.h"
#include "core/config/ConfigNode.h"

namespace rgnav {

// The keys of one level, in the listed order.
class ConfigKeyLister {
 public:
  template <class T>
  void field(const char* key, T&) { keys.emplace_back(key); }
  void degrees(const char* key, double&) { keys.emplace_back(key); }
  template <class S>
  void section(const char* key, S&) { keys.emplace_back(key); }

  std::vector<std::string> keys;
};

template <class S>
void readDescribed(const ConfigNode& node, S& target);

class ConfigReader {
 public:
  explicit ConfigReader(const ConfigNode& node) : node_(node) {}
  void field(const char* key, double& target);
  void field(const char* key, std::size_t& target);
  void field(const char* key, int& target);
  void field(const char* key, bool& target);
  void degrees(const char* key, double& radians);
  template <class S>
  void section(const char* key, S& target) { readDescribed(node_[key], target); }

 private:
  ConfigNode node_;
};

// Unknown keys are reported before missing ones: a misspelt key names itself.
template <class S>
void readDescribed(const ConfigNode& node, S& target) {
  ConfigKeyLister lister;
  S probe = target;
  describe(lister, probe);
  node.expectKeys(lister.keys);
  ConfigReader reader(node);
  describe(reader, target);
}

class ConfigWriter {
 public:
  void field(const char* key, double& value);
  void field(const char* key, std::size_t& value);
  void field(const char* key, int& value);
  void field(const char* key, bool& value);
  void degrees(const char* key, double& radians);
  template <class S>
  void section(const char* key, S& target) {
    line(key, "");
    ++depth_;
    describe(*this, target);
    --depth_;
  }
  std::string text() const { return out_.str(); }

 private:
  void line(const char* key, const std::string& value);

  std::ostringstream out_;
  int depth_ = 0;
};

// The document of a YAML text (ConfigError "not YAML" otherwise) and the text of a file
// (FileError if it cannot be read).
YAML::Node parseYamlDocument(const std::string& yamlText);
std::string readConfigFile(const std::string& file);

// `path` names the text in errors (the file it came from).
template <class S>
S parseDescribed(const std::string& yamlText, const std::string& path) {
  try {
    const ConfigVars noVariables;
    S config;
    readDescribed(ConfigNode(parseYamlDocument(yamlText), "", noVariables), config);
    return config;
  } catch (const ConfigError& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

// parseDescribed, then check(config) (the struct's own validation); an rgnav::Error it throws
// becomes a ConfigError naming `path`.
template <class S, class Check>
S parseChecked(const std::string& yamlText, const std::string& path, Check check) {
  S config = parseDescribed<S>(yamlText, path);
  try {
    check(config);
  } catch (const Error& e) {
    throw ConfigError(path + ": " + e.what());
  }
  return config;
}

template <class S>
std::string describedYaml(S config) {
  ConfigWriter writer;
  describe(writer, config);
  return writer.text();
}

}  // namespace rgnav
