// A set's processes found without its watchdog (see SetLeftovers.h).
#include "watchdog/SetLeftovers.h"

#include <algorithm>

#include "core/supervision/SupervisedModules.h"
#include "watchdog/ChildProcess.h"
#include "watchdog/ProcStat.h"
#include "watchdog/WatchdogStateFile.h"

namespace rgnav {

namespace {

std::string stateFilePath(const SetConfig& set) { return set.runDir + "/watchdog.state"; }

}  // namespace

std::vector<LeftoverModule> leftoverModules(const SetConfig& set) {
  const std::vector<ProcessRecord> records = WatchdogStateFile(stateFilePath(set)).read();
  std::vector<LeftoverModule> out;
  for (const SupervisedModule& module : supervisedModules(set)) {
    const auto it = std::find_if(records.begin(), records.end(),
                                 [&](const ProcessRecord& r) { return r.module == module.spec.name; });
    if (it != records.end() && isProcessAlive(it->pid, it->startTime))
      out.push_back({*it, processAge(it->startTime)});
  }
  return out;
}

void stopLeftovers(const SetConfig& set, const std::vector<LeftoverModule>& leftovers) {
  const std::vector<SupervisedModule> modules = supervisedModules(set);
  for (auto it = leftovers.rbegin(); it != leftovers.rend(); ++it) {
    std::optional<ChildProcess> process = ChildProcess::adopt(it->record.pid, it->record.startTime);
    if (!process) continue;  // ended meanwhile
    const auto module = std::find_if(modules.begin(), modules.end(),
                                     [&](const SupervisedModule& m) { return m.spec.name == it->record.module; });
    process->stop(module->spec.policy.stopTimeout);
  }
  WatchdogStateFile(stateFilePath(set)).write({});
}

std::vector<HeldPort> heldPorts(const SetConfig& set, const std::vector<LeftoverModule>& own) {
  std::vector<std::pair<std::string, HostPort>> endpoints{{"watchdog", {set.host, set.watchdog.port}}};
  for (const SupervisedModule& module : supervisedModules(set)) endpoints.emplace_back(module.spec.name, module.endpoint);
  std::vector<HeldPort> held;
  for (const auto& [user, endpoint] : endpoints) {
    const int port = endpoint.port;
    const bool adoptable = std::any_of(own.begin(), own.end(), [&](const LeftoverModule& m) {
      return groupListensOn(m.record.pid, port);
    });
    if (adoptable) continue;
    if (const std::optional<PortHolder> holder = findPortHolder(endpoint)) held.push_back({user, port, *holder});
  }
  return held;
}

}  // namespace rgnav
