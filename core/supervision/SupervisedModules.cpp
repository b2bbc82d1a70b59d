// The supervised modules of a set (see SupervisedModules.h).
#include "core/supervision/SupervisedModules.h"

#include <algorithm>

#include "core/supervision/StartOrder.h"

namespace rgnav {

std::vector<SupervisedModule> supervisedModules(const SetConfig& config) {
  std::vector<SupervisedModule> out;
  if (config.naming.managed) {
    ModuleSpec naming;
    naming.name = kNamingModule;
    naming.command = {"omniNames"};
    naming.port = config.naming.port;
    naming.objects = {kNamingModule};
    naming.policy = config.defaults;
    out.push_back({naming, HostPort{config.naming.host, config.naming.port}, {}});
  }
  for (const std::string& name : startOrder(config.modules)) {
    const ModuleSpec& spec = *std::find_if(config.modules.begin(), config.modules.end(),
                                           [&](const ModuleSpec& m) { return m.name == name; });
    SupervisedModule module{spec, HostPort{config.host, spec.port}, spec.after};
    if (config.naming.managed) module.dependencies.push_back(kNamingModule);
    out.push_back(std::move(module));
  }
  return out;
}

}  // namespace rgnav
