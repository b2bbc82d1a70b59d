// A server set (config/sets/<set>.yaml): which modules one host's watchdog runs, where they and
// the naming service listen, and how each module is restarted. Parsing is strict: an unknown
// key, a missing key, a wrong type or an out-of-range value is a ConfigError naming the key path.
#pragma once

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "core/supervision/ModulePolicy.h"
#include "core/config/VarExpansion.h"

namespace rgnav {

struct ModuleSpec {
  std::string name;
  std::vector<std::string> command;  // argv, ${VAR} expanded
  int port = 0;                      // fixed endpoint port of the server
  std::vector<std::string> objects;  // published as RGNav/<robot>/<object>; the first is pinged
  std::vector<std::string> after;    // modules that must be started before this one
  std::map<std::string, std::string> env;
  ModulePolicy policy;  // set defaults overridden by the module's own keys
};

struct NamingConfig {
  std::string host;
  int port = 0;
  bool managed = true;  // this host's watchdog runs omniNames itself
};

struct WatchdogConfig {
  int port = 0;
  std::chrono::nanoseconds heartbeatPeriod = std::chrono::milliseconds(100);
  std::chrono::nanoseconds heartbeatTimeout = std::chrono::milliseconds(250);
  int hangMisses = 2;  // consecutive missed pings before a module counts as hung
};

struct SetConfig {
  std::string name;  // the set's name, e.g. "intel"
  std::string robot = "tumbot";
  std::string host;    // address this host's servers publish
  std::string runDir;  // absolute, or relative to the caller's working directory
  NamingConfig naming;
  WatchdogConfig watchdog;
  ModulePolicy defaults;
  std::vector<ModuleSpec> modules;  // in file order
};

// Parses a set from YAML text. `setName` gives the default run dir run/<setName>; a relative
// run_dir is taken relative to `baseDir`.
SetConfig parseSetConfig(const std::string& yamlText, const std::string& setName,
                         const ConfigVars& vars, const std::string& baseDir);

// Loads config/sets/<set>.yaml; the set name is the file name without extension. A missing or
// unreadable file is a FileError; ConfigError messages start with the path.
SetConfig loadSetConfig(const std::string& path, const ConfigVars& vars, const std::string& baseDir);

}  // namespace rgnav
