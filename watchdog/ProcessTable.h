// The watchdog's module processes by module name: start or adopt, reap all of them in one
// call, and list the live ones for the state file.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/supervision/ModuleProcesses.h"
#include "core/supervision/ProcessRecord.h"
#include "watchdog/ChildProcess.h"

namespace rgnav {

class ProcessTable {
 public:
  // Throws InvalidArgumentError if the module already has a process, else see spawnProcess.
  ChildProcess& start(const std::string& module, const SpawnSpec& spec);
  // False if the recorded process is gone or its PID now belongs to another process; throws
  // InvalidArgumentError if the module already has a process.
  bool adopt(const ProcessRecord& record);
  // nullptr if the module has no process.
  ChildProcess* find(const std::string& module);
  // Polls every process (see ChildProcess::poll); ended ones are returned and removed.
  std::vector<ModuleExit> poll(SupervisionClock::time_point now);
  // The processes in the table, by module name.
  std::vector<ProcessRecord> records() const;

 private:
  void expectFree(const std::string& module) const;

  std::map<std::string, ChildProcess> processes_;
};

}  // namespace rgnav
