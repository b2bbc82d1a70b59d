// The processes of one server set (see SetProcesses.h).
#include "watchdog/SetProcesses.h"

#include <signal.h>

#include <filesystem>

#include "core/common/Errors.h"
#include "watchdog/ProcStat.h"

namespace rgnav {

namespace fs = std::filesystem;

SetProcesses::SetProcesses(const SetConfig& config, SupervisionEvents& events)
    : runDir_(config.runDir),
      robot_(config.robot),
      naming_{config.naming.host, config.naming.port},
      events_(events),
      stateFile_(config.runDir + "/watchdog.state") {
  for (SupervisedModule& m : supervisedModules(config)) modules_.emplace(m.spec.name, std::move(m));
}

SpawnSpec SetProcesses::spawnSpec(const SupervisedModule& module) const {
  SpawnSpec spec;
  spec.logFile = runDir_ + "/logs/" + module.spec.name + ".log";
  spec.env = module.spec.env;
  if (module.spec.name == kNamingModule) {
    const std::string dataDir = runDir_ + "/naming";
    fs::create_directories(dataDir);
    bool hasData = false;
    for (const auto& entry : fs::directory_iterator(dataDir))
      hasData |= entry.path().filename().string().starts_with("omninames-") && entry.path().extension() == ".dat";
    spec.argv = {"omniNames", "-logdir", dataDir, "-ORBendPoint", "giop:tcp:" + module.endpoint.str()};
    if (!hasData) spec.argv.insert(spec.argv.end(), {"-start", std::to_string(module.endpoint.port)});
    return spec;
  }
  const std::string stateDir = runDir_ + "/state/" + module.spec.name;
  spec.argv = module.spec.command;
  spec.argv.insert(spec.argv.end(), {"--module", module.spec.name, "--robot", robot_, "--endpoint",
                                     module.endpoint.str(), "--naming", naming_.str(), "--state-dir", stateDir});
  return spec;
}

pid_t SetProcesses::start(const std::string& module) {
  const pid_t pid = table_.start(module, spawnSpec(modules_.at(module))).pid();
  saveState();
  return pid;
}

std::optional<std::chrono::nanoseconds> SetProcesses::adopt(const ProcessRecord& record) {
  if (!table_.adopt(record)) return std::nullopt;
  saveState();
  return processAge(record.startTime);
}

void SetProcesses::kill(const std::string& module) {
  if (ChildProcess* child = table_.find(module)) child->signalGroup(SIGKILL);
}

void SetProcesses::requestStop(const std::string& module, SupervisionClock::time_point now,
                               std::chrono::nanoseconds timeout) {
  if (ChildProcess* child = table_.find(module)) child->requestStop(now, timeout);
}

std::vector<ModuleExit> SetProcesses::reap(SupervisionClock::time_point now) {
  std::vector<ModuleExit> exits = table_.poll(now);
  if (!exits.empty()) saveState();
  return exits;
}

void SetProcesses::saveState() {
  try {
    stateFile_.write(table_.records());
  } catch (const Error& e) {
    events_.record("-", "state-unwritable", e.what());
  }
}

}  // namespace rgnav
