// Strict, path-aware access to a parsed YAML config tree. Every error is a ConfigError that
// names the key path ("modules[2].port") and the line. Shared by every YAML loader (rgnav_config).
#pragma once

#include <yaml-cpp/yaml.h>

#include <chrono>
#include <string>
#include <vector>

#include "core/config/VarExpansion.h"

namespace rgnav {

class ConfigNode {
 public:
  ConfigNode(YAML::Node node, std::string path, const ConfigVars& vars);

  const std::string& path() const { return path_; }
  [[noreturn]] void fail(const std::string& what) const;

  // Requires a mapping whose keys are all in `allowed`, each at most once.
  void expectKeys(const std::vector<std::string>& allowed) const;
  bool has(const std::string& key) const;
  ConfigNode operator[](const std::string& key) const;  // a required key
  std::vector<ConfigNode> items() const;                // elements of a sequence

  std::string asString() const;  // a scalar, with ${VAR} expanded
  long long asInteger(long long min, long long max) const;
  double asDouble() const;  // finite
  bool asBool() const;
  std::chrono::nanoseconds asSeconds(double min, bool minInclusive) const;  // at most 1e6 s
  std::vector<std::string> asStringList() const;
  std::vector<std::pair<std::string, std::string>> asStringMap() const;  // keys as written

 private:
  ConfigNode child(const std::string& key, YAML::Node node) const;
  void expectKind(bool ok, const char* expected) const;

  YAML::Node node_;
  std::string path_;
  const ConfigVars* vars_;
};

}  // namespace rgnav
