// SetProcesses: the real ModuleProcesses of one server set: fork/exec with the module's
// command line and log file (omniNames for a managed naming service), waitpid and /proc
// through ProcessTable, and the state file (run_dir/watchdog.state), rewritten whenever a
// process starts, is adopted or ends, so that a restarted watchdog can adopt what still runs.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/supervision/ModuleProcesses.h"
#include "core/supervision/SupervisedModules.h"
#include "core/supervision/SupervisionEvents.h"
#include "watchdog/ProcessTable.h"
#include "watchdog/WatchdogStateFile.h"

namespace rgnav {

class SetProcesses : public ModuleProcesses {
 public:
  // events receives "state-unwritable" when the state file cannot be written.
  SetProcesses(const SetConfig& config, SupervisionEvents& events);

  pid_t start(const std::string& module) override;
  std::optional<std::chrono::nanoseconds> adopt(const ProcessRecord& record) override;
  void kill(const std::string& module) override;
  void requestStop(const std::string& module, SupervisionClock::time_point now,
                   std::chrono::nanoseconds timeout) override;
  std::vector<ModuleExit> reap(SupervisionClock::time_point now) override;

  // What a previous watchdog left (see WatchdogStateFile::read for the errors).
  std::vector<ProcessRecord> readState() const { return stateFile_.read(); }
  // Writes the processes of the table to the state file.
  void saveState();

 private:
  SpawnSpec spawnSpec(const SupervisedModule& module) const;

  std::string runDir_;
  std::string robot_;
  HostPort naming_;
  std::map<std::string, SupervisedModule> modules_;
  SupervisionEvents& events_;
  WatchdogStateFile stateFile_;
  ProcessTable table_;
};

}  // namespace rgnav
