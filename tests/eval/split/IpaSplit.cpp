// Strict loading of the IPA tuning/check split and the per-set figure line (see IpaSplit.h).
#include "tests/eval/split/IpaSplit.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/common/Errors.h"
#include "core/config/ConfigNode.h"

namespace rgnav {

namespace {

constexpr const char* kFurnishedSuffix = "_furnitures";

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string figuresOf(const char* set, std::size_t maps, const std::vector<Figure>& figures) {
  std::string text = std::string(" maps_") + set + "=" + std::to_string(maps);
  for (const Figure& f : figures) {
    char value[32];
    if (maps == 0)
      std::snprintf(value, sizeof value, "n/a");
    else
      std::snprintf(value, sizeof value, "%.3f", f.value);
    text += " " + f.key + "_" + set + "=" + value;
  }
  return text;
}

}  // namespace

IpaSplit::IpaSplit(std::vector<std::string> tuning, std::vector<std::string> check)
    : tuning_(std::move(tuning)), check_(std::move(check)) {}

MapSet IpaSplit::setOf(const std::string& floorPlanPath) const {
  const std::string name = ipaMapName(floorPlanPath);
  if (contains(tuning_, name)) return MapSet::kTuning;
  if (contains(check_, name)) return MapSet::kCheck;
  throw ConfigError("map " + name + " (" + floorPlanPath + ") is in neither the tuning nor the check set of the "
                    "IPA split (config/eval/ipa-split.yaml)");
}

IpaSplit parseIpaSplit(const std::string& yamlText) {
  YAML::Node document;
  try {
    document = YAML::Load(yamlText);
  } catch (const YAML::Exception& e) {
    throw ConfigError(std::string("not YAML: ") + e.what());
  }
  const ConfigVars noVariables;
  const ConfigNode root(document, "", noVariables);
  root.expectKeys({"tuning", "check"});
  std::vector<std::string> sets[2];
  std::set<std::string> seen;
  for (const auto& [key, names] : {std::pair{"tuning", &sets[0]}, std::pair{"check", &sets[1]}}) {
    const ConfigNode list = root[key];
    *names = list.asStringList();
    if (names->empty()) list.fail("names no map");
    for (const std::string& name : *names)
      if (!seen.insert(name).second) list.fail("names " + name + " a second time");
  }
  return IpaSplit(std::move(sets[0]), std::move(sets[1]));
}

IpaSplit loadIpaSplit(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw FileError(path + ": cannot read the IPA split");
  std::ostringstream text;
  text << in.rdbuf();
  try {
    return parseIpaSplit(text.str());
  } catch (const ConfigError& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

std::string ipaMapName(const std::string& floorPlanPath) {
  std::string stem = std::filesystem::path(floorPlanPath).stem().string();
  const std::string suffix = kFurnishedSuffix;
  if (stem.size() > suffix.size() && stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0)
    stem.resize(stem.size() - suffix.size());
  return stem;
}

std::string splitFiguresLine(const std::string& label, std::size_t tuningMaps, const std::vector<Figure>& tuning,
                             std::size_t checkMaps, const std::vector<Figure>& check) {
  return label + ":" + figuresOf("tuning", tuningMaps, tuning) + figuresOf("check", checkMaps, check);
}

}  // namespace rgnav
