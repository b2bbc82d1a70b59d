// Bookkeeping of module processes by name.
#include "watchdog/ProcessTable.h"

#include "core/common/Errors.h"

namespace rgnav {

void ProcessTable::expectFree(const std::string& module) const {
  if (processes_.count(module)) {
    throw InvalidArgumentError("module " + module + " already has process " +
                               std::to_string(processes_.at(module).pid()));
  }
}

ChildProcess& ProcessTable::start(const std::string& module, const SpawnSpec& spec) {
  expectFree(module);
  return processes_.emplace(module, ChildProcess::start(spec)).first->second;
}

bool ProcessTable::adopt(const ProcessRecord& record) {
  expectFree(record.module);
  std::optional<ChildProcess> process = ChildProcess::adopt(record.pid, record.startTime);
  if (!process) return false;
  processes_.emplace(record.module, std::move(*process));
  return true;
}

ChildProcess* ProcessTable::find(const std::string& module) {
  const auto it = processes_.find(module);
  return it == processes_.end() ? nullptr : &it->second;
}

std::vector<ModuleExit> ProcessTable::poll(SupervisionClock::time_point now) {
  std::vector<ModuleExit> exits;
  for (auto it = processes_.begin(); it != processes_.end();) {
    if (const std::optional<ExitStatus> status = it->second.poll(now)) {
      exits.push_back({it->first, it->second.pid(), *status});
      it = processes_.erase(it);
    } else {
      ++it;
    }
  }
  return exits;
}

std::vector<ProcessRecord> ProcessTable::records() const {
  std::vector<ProcessRecord> out;
  for (const auto& [module, process] : processes_) out.push_back({module, process.pid(), process.startTime()});
  return out;
}

}  // namespace rgnav
