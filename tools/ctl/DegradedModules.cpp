// Asking the running modules of a set whether they are degraded (see DegradedModules.h).
#include "tools/ctl/DegradedModules.h"

#include <algorithm>

#include "clientlibs/common/ModuleClient.h"
#include "core/common/Errors.h"

namespace rgnav {

std::map<std::string, std::string> degradedModules(const SetConfig& set, ClientSettings settings,
                                                   const std::vector<ModuleProcessInfo>& modules) {
  settings.callTimeout = settings.connectTimeout = std::chrono::milliseconds(300);
  settings.retryBudget = std::chrono::milliseconds(0);
  std::map<std::string, std::string> degraded;
  for (const ModuleSpec& spec : set.modules) {
    const auto info = std::find_if(modules.begin(), modules.end(), [&](const auto& m) { return m.name == spec.name; });
    if (info == modules.end() || info->state != ProcessState::Running || spec.objects.empty()) continue;
    try {
      const ModuleStatusInfo status = ModuleClient(spec.objects.front(), settings, HostPort{set.host, spec.port}).status();
      if (status.state == ModuleRunState::Degraded) degraded[spec.name] = status.lastError;
    } catch (const Error&) {
      // Not answering now: the watchdog's pings judge that.
    }
  }
  return degraded;
}

}  // namespace rgnav
