// The modules a set's watchdog supervises, in start order: a managed naming service first (as
// the module "NameService", which every other module then depends on), then the set's modules
// in dependency order, each with the endpoint it listens on.
#pragma once

#include <string>
#include <vector>

#include "core/common/HostPort.h"
#include "core/supervision/SetConfig.h"

namespace rgnav {

inline constexpr const char* kNamingModule = "NameService";

struct SupervisedModule {
  ModuleSpec spec;
  HostPort endpoint;
  std::vector<std::string> dependencies;  // must answer pings before this module starts
};

// Throws ConfigError as startOrder does.
std::vector<SupervisedModule> supervisedModules(const SetConfig& config);

}  // namespace rgnav
