// The reading and writing visitors of described parameter structs (see DescribedConfig.h).
#include "core/config/DescribedConfig.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string_view>

#include "core/common/Errors.h"

namespace rgnav {
namespace {

// The same expression order as the code's defaults ("5.0 * M_PI / 180.0"), so that a whole
// number of degrees gives exactly the default's radians.
double radiansOf(double degrees) { return degrees * M_PI / 180.0; }

std::string shortest(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// The shortest decimal number of degrees that reads back to exactly `radians`.
std::string degreesText(double radians) {
  const double degrees = radians * 180.0 / M_PI;
  for (int precision = 1; precision <= std::numeric_limits<double>::max_digits10; ++precision) {
    char buffer[64];
    const auto result =
        std::to_chars(buffer, buffer + sizeof buffer, degrees, std::chars_format::general, precision);
    double parsed = 0;
    std::from_chars(buffer, result.ptr, parsed);
    if (radiansOf(parsed) == radians) return shortest(parsed);  // "20", not "2e+01"
  }
  throw ConfigError(shortest(radians) + " rad has no number of degrees that reads back to it");
}

void expectDegreeKey(const char* key) {
  const std::string_view name(key);
  if (name.size() < 4 || name.substr(name.size() - 4) != "_deg") {
    throw ConfigError(std::string(key) + ": an angle in degrees needs a key ending in _deg");
  }
}

}  // namespace

void ConfigReader::field(const char* key, double& target) { target = node_[key].asDouble(); }

void ConfigReader::field(const char* key, std::size_t& target) {
  target = static_cast<std::size_t>(node_[key].asInteger(0, std::numeric_limits<std::int64_t>::max()));
}

void ConfigReader::field(const char* key, int& target) {
  target = static_cast<int>(node_[key].asInteger(std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}

void ConfigReader::field(const char* key, bool& target) { target = node_[key].asBool(); }

void ConfigReader::degrees(const char* key, double& radians) {
  expectDegreeKey(key);
  radians = radiansOf(node_[key].asDouble());
}

void ConfigWriter::field(const char* key, double& value) { line(key, shortest(value)); }

void ConfigWriter::field(const char* key, std::size_t& value) { line(key, std::to_string(value)); }

void ConfigWriter::field(const char* key, int& value) { line(key, std::to_string(value)); }

void ConfigWriter::field(const char* key, bool& value) { line(key, value ? "true" : "false"); }

void ConfigWriter::degrees(const char* key, double& radians) {
  expectDegreeKey(key);
  line(key, degreesText(radians));
}

void ConfigWriter::line(const char* key, const std::string& value) {
  out_ << std::string(2 * static_cast<std::size_t>(depth_), ' ') << key << ':';
  if (!value.empty()) out_ << ' ' << value;
  out_ << '\n';
}

YAML::Node parseYamlDocument(const std::string& yamlText) {
  try {
    return YAML::Load(yamlText);
  } catch (const YAML::Exception& e) {
    throw ConfigError(std::string("not YAML: ") + e.what());
  }
}

std::string readConfigFile(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw FileError(file + ": cannot read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace rgnav
