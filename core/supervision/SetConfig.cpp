// Strict parser of server-set files: schema, defaults, ${VAR} expansion and cross-checks
// (unique names and ports, known `after` targets, no dependency cycle).
#include "core/supervision/SetConfig.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/common/Errors.h"
#include "core/config/ConfigNode.h"
#include "core/supervision/StartOrder.h"

namespace rgnav {
namespace {

const std::vector<std::string> kPolicyKeys = {"restart",           "max_restarts",    "restart_window_s",
                                              "backoff_initial_s", "backoff_max_s",   "start_timeout_s",
                                              "stop_timeout_s"};

std::vector<std::string> withPolicyKeys(std::vector<std::string> keys) {
  keys.insert(keys.end(), kPolicyKeys.begin(), kPolicyKeys.end());
  return keys;
}

// Names that become part of a naming-service path or an environment: no separators, no spaces.
std::string readName(const ConfigNode& node) {
  const std::string name = node.asString();
  const bool ok = !name.empty() && name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                          "0123456789_-") == std::string::npos;
  if (!ok) node.fail("bad name \"" + name + "\": use letters, digits, '_' and '-'");
  return name;
}

std::string readNonEmpty(const ConfigNode& node) {
  const std::string value = node.asString();
  if (value.empty()) node.fail("must not be empty");
  return value;
}

int readPort(const ConfigNode& node) { return static_cast<int>(node.asInteger(1, 65535)); }

// Reads the policy keys present in `map` on top of `base`.
ModulePolicy readPolicy(const ConfigNode& map, ModulePolicy policy) {
  if (map.has("restart")) {
    const ConfigNode node = map["restart"];
    const auto parsed = parseRestartPolicy(node.asString());
    if (!parsed) node.fail("out of range: expected permanent, transient or temporary");
    policy.restart = *parsed;
  }
  if (map.has("max_restarts")) policy.maxRestarts = static_cast<int>(map["max_restarts"].asInteger(0, 1000000));
  if (map.has("restart_window_s")) policy.restartWindow = map["restart_window_s"].asSeconds(0, false);
  if (map.has("backoff_initial_s")) policy.backoffInitial = map["backoff_initial_s"].asSeconds(0, true);
  if (map.has("backoff_max_s")) policy.backoffMax = map["backoff_max_s"].asSeconds(0, true);
  if (map.has("start_timeout_s")) policy.startTimeout = map["start_timeout_s"].asSeconds(0, false);
  if (map.has("stop_timeout_s")) policy.stopTimeout = map["stop_timeout_s"].asSeconds(0, false);
  if (policy.backoffMax < policy.backoffInitial) map.fail("backoff_max_s is smaller than backoff_initial_s");
  return policy;
}

NamingConfig readNaming(const ConfigNode& node) {
  node.expectKeys({"host", "port", "managed"});
  NamingConfig naming;
  naming.host = readNonEmpty(node["host"]);
  naming.port = readPort(node["port"]);
  if (node.has("managed")) naming.managed = node["managed"].asBool();
  return naming;
}

WatchdogConfig readWatchdog(const ConfigNode& node) {
  node.expectKeys({"port", "heartbeat_period_s", "heartbeat_timeout_s", "hang_misses"});
  WatchdogConfig watchdog;
  watchdog.port = readPort(node["port"]);
  if (node.has("heartbeat_period_s")) watchdog.heartbeatPeriod = node["heartbeat_period_s"].asSeconds(0, false);
  if (node.has("heartbeat_timeout_s")) watchdog.heartbeatTimeout = node["heartbeat_timeout_s"].asSeconds(0, false);
  if (node.has("hang_misses")) watchdog.hangMisses = static_cast<int>(node["hang_misses"].asInteger(1, 1000));
  return watchdog;
}

std::vector<std::string> readNonEmptyList(const ConfigNode& node) {
  std::vector<std::string> list = node.asStringList();
  if (list.empty()) node.fail("must not be empty");
  return list;
}

ModuleSpec readModule(const ConfigNode& node, const ModulePolicy& defaults) {
  node.expectKeys(withPolicyKeys({"name", "command", "port", "objects", "after", "env"}));
  ModuleSpec m;
  m.name = readName(node["name"]);
  m.command = readNonEmptyList(node["command"]);
  if (m.command.front().empty()) node["command"].items().front().fail("must not be empty");
  m.port = readPort(node["port"]);
  const ConfigNode objects = node["objects"];
  if (objects.items().empty()) objects.fail("must not be empty");
  for (const ConfigNode& object : objects.items()) m.objects.push_back(readName(object));
  if (node.has("after")) m.after = node["after"].asStringList();
  if (node.has("env")) {
    for (const auto& [key, value] : node["env"].asStringMap()) {
      const bool ok = !key.empty() && key.find_first_of("=\0", 0, 2) == std::string::npos;
      if (!ok) node["env"].fail("bad variable name \"" + key + "\"");
      m.env[key] = value;
    }
  }
  m.policy = readPolicy(node, defaults);
  return m;
}

// Names, objects and ports must be unique; `after` must name modules of the set.
void crossCheck(const SetConfig& set, const std::vector<ConfigNode>& moduleNodes) {
  std::map<int, std::string> portOwner{{set.watchdog.port, "watchdog.port"}};
  if (set.naming.managed && !portOwner.emplace(set.naming.port, "naming.port").second) {
    throw ConfigError("naming.port: port " + std::to_string(set.naming.port) + " already used by watchdog.port");
  }
  std::map<std::string, std::string> nameOwner;
  std::map<std::string, std::string> objectOwner;
  for (std::size_t i = 0; i < set.modules.size(); ++i) {
    const ModuleSpec& m = set.modules[i];
    const ConfigNode& node = moduleNodes[i];
    if (!nameOwner.emplace(m.name, node.path()).second) {
      node["name"].fail("duplicate module name \"" + m.name + "\" (also " + nameOwner[m.name] + ")");
    }
    if (!portOwner.emplace(m.port, node.path() + ".port").second) {
      node["port"].fail("port " + std::to_string(m.port) + " already used by " + portOwner[m.port]);
    }
    for (const std::string& object : m.objects) {
      if (!objectOwner.emplace(object, m.name).second) {
        node["objects"].fail("object \"" + object + "\" already published by module " + objectOwner[object]);
      }
    }
  }
  for (std::size_t i = 0; i < set.modules.size(); ++i) {
    const std::vector<ConfigNode> after = moduleNodes[i].has("after") ? moduleNodes[i]["after"].items()
                                                                       : std::vector<ConfigNode>{};
    for (std::size_t k = 0; k < after.size(); ++k) {
      if (!nameOwner.count(set.modules[i].after[k])) {
        after[k].fail("unknown module \"" + set.modules[i].after[k] + "\"");
      }
    }
  }
  try {
    startOrder(set.modules);
  } catch (const ConfigError& e) {
    throw ConfigError(std::string("modules: ") + e.what());
  }
}

YAML::Node parseYaml(const std::string& yamlText) {
  try {
    return YAML::Load(yamlText);
  } catch (const YAML::Exception& e) {
    throw ConfigError("line " + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
}

}  // namespace

SetConfig parseSetConfig(const std::string& yamlText, const std::string& setName, const ConfigVars& vars,
                         const std::string& baseDir) {
  const ConfigNode root(parseYaml(yamlText), "", vars);
  root.expectKeys({"robot", "host", "naming", "run_dir", "watchdog", "defaults", "modules"});
  SetConfig set;
  set.name = setName;
  if (root.has("robot")) set.robot = readName(root["robot"]);
  set.host = readNonEmpty(root["host"]);
  set.naming = readNaming(root["naming"]);
  const std::filesystem::path runDir = root.has("run_dir") ? readNonEmpty(root["run_dir"]) : "run/" + setName;
  set.runDir = (runDir.is_absolute() ? runDir : std::filesystem::path(baseDir) / runDir).lexically_normal().string();
  set.watchdog = readWatchdog(root["watchdog"]);
  if (root.has("defaults")) {
    const ConfigNode defaults = root["defaults"];
    defaults.expectKeys(kPolicyKeys);
    set.defaults = readPolicy(defaults, ModulePolicy{});
  }
  const std::vector<ConfigNode> moduleNodes = root["modules"].items();
  if (moduleNodes.empty()) root["modules"].fail("must not be empty");
  for (const ConfigNode& node : moduleNodes) set.modules.push_back(readModule(node, set.defaults));
  crossCheck(set, moduleNodes);
  return set;
}

SetConfig loadSetConfig(const std::string& path, const ConfigVars& vars, const std::string& baseDir) {
  std::ifstream in(path);
  if (!in) throw FileError("cannot open server-set file " + path);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw FileError("cannot read server-set file " + path);
  try {
    return parseSetConfig(text.str(), std::filesystem::path(path).stem().string(), vars, baseDir);
  } catch (const ConfigError& e) {
    throw ConfigError(path + ": " + e.what());
  }
}

}  // namespace rgnav
