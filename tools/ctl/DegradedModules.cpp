// Asking the running modules of a set whether they are degraded (see DegradedModules.h).
#include "tools/ctl/DegradedModules.h"

#include <algorithm>
#include <future>

#include "clientlibs/common/ModuleClient.h"
#include "core/common/Errors.h"

namespace rgnav {

std::map<std::string, std::string> degradedModules(const SetConfig& set, ClientSettings settings,
                                                   const std::vector<ModuleProcessInfo>& modules) {
  settings.callTimeout = settings.connectTimeout = std::chrono::milliseconds(300);
  settings.retryBudget = std::chrono::milliseconds(0);
  settings.firstContactBudget.reset();  // one try, also at first contact
  // All at once, so that modules slow to answer do not add up.
  std::map<std::string, std::future<ModuleStatusInfo>> asked;
  for (const ModuleSpec& spec : set.modules) {
    const auto info = std::find_if(modules.begin(), modules.end(), [&](const auto& m) { return m.name == spec.name; });
    if (info == modules.end() || info->state != ProcessState::Running || spec.objects.empty()) continue;
    asked[spec.name] = std::async(std::launch::async, [&settings, endpoint = HostPort{set.host, spec.port},
                                                       object = spec.objects.front()] {
      return ModuleClient(object, settings, endpoint).status();
    });
  }
  std::map<std::string, std::string> degraded;
  for (auto& [name, status] : asked) {
    try {
      const ModuleStatusInfo s = status.get();
      if (s.state == ModuleRunState::Degraded) degraded[name] = s.lastError;
    } catch (const Error&) {
      // Not answering now: the watchdog's pings judge that.
    }
  }
  return degraded;
}

}  // namespace rgnav
