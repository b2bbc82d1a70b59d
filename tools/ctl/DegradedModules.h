// degradedModules: what the watchdog cannot see. It judges a module alive by its pings and keeps
// it RUNNING; a module that lives but cannot do all of its job (e.g. cannot write its
// checkpoints) says so in its own status(): MODULE_DEGRADED with the reason as lastError
// (Module.idl). For each module the watchdog reports RUNNING this asks its status() directly at
// <set host>:<port>/<first object>, all at once and briefly; one that does not answer at once is
// left as the watchdog sees it.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "clientlibs/common/ClientSettings.h"
#include "clientlibs/watchdog/WatchdogTypes.h"
#include "core/supervision/SetConfig.h"

namespace rgnav {

// The degraded modules among `modules`, each with its reason.
std::map<std::string, std::string> degradedModules(const SetConfig& set, ClientSettings settings,
                                                   const std::vector<ModuleProcessInfo>& modules);

}  // namespace rgnav
