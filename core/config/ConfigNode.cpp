// Typed, strict reading of YAML nodes with key paths in every error.
#include "core/config/ConfigNode.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

constexpr double kMaxSeconds = 1e6;

std::string formatNumber(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}

}  // namespace

ConfigNode::ConfigNode(YAML::Node node, std::string path, const ConfigVars& vars)
    : node_(std::move(node)), path_(std::move(path)), vars_(&vars) {}

void ConfigNode::fail(const std::string& what) const {
  const YAML::Mark mark = node_.Mark();
  std::string where = path_.empty() ? std::string("top level") : path_;
  std::string line = mark.is_null() ? std::string() : " (line " + std::to_string(mark.line + 1) + ")";
  throw ConfigError(where + ": " + what + line);
}

void ConfigNode::expectKind(bool ok, const char* expected) const {
  if (!ok) fail(std::string("wrong type, expected ") + expected);
}

ConfigNode ConfigNode::child(const std::string& key, YAML::Node node) const {
  return ConfigNode(std::move(node), path_.empty() ? key : path_ + "." + key, *vars_);
}

void ConfigNode::expectKeys(const std::vector<std::string>& allowed) const {
  expectKind(node_.IsMap(), "a mapping");
  std::set<std::string> seen;
  for (const auto& entry : node_) {
    if (!entry.first.IsScalar()) child("?", entry.first).fail("key is not a scalar");
    const std::string key = entry.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      child(key, entry.first).fail("unknown key");
    }
    if (!seen.insert(key).second) child(key, entry.first).fail("duplicate key");
  }
}

bool ConfigNode::has(const std::string& key) const {
  return node_.IsMap() && static_cast<bool>(node_[key]);
}

ConfigNode ConfigNode::operator[](const std::string& key) const {
  expectKind(node_.IsMap(), "a mapping");
  const YAML::Node value = node_[key];
  if (!value) child(key, node_).fail("missing required key");
  return child(key, value);
}

std::vector<ConfigNode> ConfigNode::items() const {
  expectKind(node_.IsSequence(), "a list");
  std::vector<ConfigNode> out;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    out.emplace_back(node_[i], path_ + "[" + std::to_string(i) + "]", *vars_);
  }
  return out;
}

std::string ConfigNode::asString() const {
  expectKind(node_.IsScalar(), "a string");
  try {
    return expandVariables(node_.Scalar(), *vars_);
  } catch (const ConfigError& e) {
    fail(e.what());
  }
}

long long ConfigNode::asInteger(long long min, long long max) const {
  expectKind(node_.IsScalar(), "an integer");
  long long value = 0;
  try {
    value = node_.as<long long>();
  } catch (const YAML::Exception&) {
    fail("wrong type, expected an integer, got \"" + node_.Scalar() + "\"");
  }
  if (value < min || value > max) {
    fail("out of range: " + std::to_string(value) + " not in [" + std::to_string(min) + ", " +
         std::to_string(max) + "]");
  }
  return value;
}

double ConfigNode::asDouble() const {
  expectKind(node_.IsScalar(), "a number");
  double value = 0;
  try {
    value = node_.as<double>();
  } catch (const YAML::Exception&) {
    fail("wrong type, expected a number, got \"" + node_.Scalar() + "\"");
  }
  if (!std::isfinite(value)) fail("out of range: not a finite number");
  return value;
}

bool ConfigNode::asBool() const {
  expectKind(node_.IsScalar(), "true or false");
  try {
    return node_.as<bool>();
  } catch (const YAML::Exception&) {
    fail("wrong type, expected true or false, got \"" + node_.Scalar() + "\"");
  }
}

std::chrono::nanoseconds ConfigNode::asSeconds(double min, bool minInclusive) const {
  const double s = asDouble();
  const bool aboveMin = minInclusive ? s >= min : s > min;
  if (!aboveMin || s > kMaxSeconds) {
    fail("out of range: " + formatNumber(s) + " s not in " + (minInclusive ? "[" : "(") +
         formatNumber(min) + ", " + formatNumber(kMaxSeconds) + "]");
  }
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(s));
}

std::vector<std::string> ConfigNode::asStringList() const {
  std::vector<std::string> out;
  for (const ConfigNode& item : items()) out.push_back(item.asString());
  return out;
}

std::vector<std::pair<std::string, std::string>> ConfigNode::asStringMap() const {
  expectKind(node_.IsMap(), "a mapping");
  std::vector<std::pair<std::string, std::string>> out;
  std::set<std::string> seen;
  for (const auto& entry : node_) {
    if (!entry.first.IsScalar()) child("?", entry.first).fail("key is not a scalar");
    const std::string key = entry.first.Scalar();
    if (!seen.insert(key).second) child(key, entry.first).fail("duplicate key");
    out.emplace_back(key, child(key, entry.second).asString());
  }
  return out;
}

}  // namespace rgnav
