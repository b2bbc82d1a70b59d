// SupervisedSet: the modules of one server set as the watchdog supervises them: a start in
// dependency order (a module starts once the modules it comes after answer pings), heartbeats
// (hung = hang_misses pings unanswered in a row, or no answer within start_timeout after a
// start: the process group is SIGKILLed), exits detected by reaping, restarts decided by each
// module's RestartTracker (policy, N restarts in T seconds then FATAL, backoff), operator stop /
// start / restart of one module without touching the others, and an orderly stop in reverse
// order. A managed naming service is supervised like a module named "NameService".
//
// If the watchdog itself dies, the modules keep running: they lead their own process groups.
// The state file (run_dir/watchdog.state) names each module's PID and start time; a restarted
// watchdog adopts the live ones (watching them by heartbeat and /proc, since they are no longer
// its children) and starts only what is missing.
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "clientlibs/watchdog/WatchdogTypes.h"
#include "core/common/HostPort.h"
#include "core/supervision/RestartTracker.h"
#include "core/supervision/SetConfig.h"
#include "watchdog/EventLog.h"
#include "watchdog/ProcessTable.h"
#include "watchdog/WatchdogStateFile.h"

namespace rgnav {

// Answers whether one module is alive; made once per module and used by its heartbeat thread.
using ProbeFactory = std::function<std::function<bool()>(const ModuleSpec& module, const HostPort& endpoint)>;

class SupervisedSet {
 public:
  static constexpr const char* kNamingModule = "NameService";

  SupervisedSet(SetConfig config, ProbeFactory probes);
  ~SupervisedSet();
  SupervisedSet(const SupervisedSet&) = delete;
  SupervisedSet& operator=(const SupervisedSet&) = delete;

  // Adopts what a previous watchdog left running, then starts the rest in dependency order.
  void start();
  // Stops every module in reverse start order (the naming service last) and waits for them.
  void stopAll();

  std::vector<ModuleProcessInfo> modules() const;
  // InvalidArgumentError for a module the set does not have.
  ModuleProcessInfo describe(const std::string& name) const;
  void stopModule(const std::string& name);
  void startModule(const std::string& name);
  void restartModule(const std::string& name);
  std::vector<SupervisionEvent> eventsSince(std::uint64_t afterId, std::size_t maxCount) const;

 private:
  struct Module;

  void monitor();                      // runs superviseOnce every tick
  void superviseOnce(SupervisionClock::time_point now);  // reaping, restarts, start timeouts, pending starts; under lock
  void stopAndWait(Module& module);
  void heartbeat(Module& module);      // one thread per module
  // First start, automatic restart (the only kind counted in `restarts`), or by the operator.
  enum class Launch { First, Restart, OperatorStart, OperatorRestart };
  void launch(Module& module, Launch kind);  // under lock
  void handleExit(Module& module, const ExitStatus& status);  // under lock
  void markHung(Module& module, const std::string& why);     // under lock
  bool dependenciesReady(const Module& module) const;        // under lock
  void saveState();                                          // under lock
  void joinThreads();
  SpawnSpec spawnSpec(const Module& module) const;
  Module& find(const std::string& name);
  const Module& find(const std::string& name) const;
  void event(Module& module, const std::string& what, const std::string& detail);
  void record(const std::string& module, const std::string& what, const std::string& detail);

  SetConfig config_;
  ProbeFactory probes_;
  EventLog events_;
  WatchdogStateFile stateFile_;
  std::vector<std::unique_ptr<Module>> modules_;  // start order (naming service first)

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  ProcessTable processes_;
  bool shuttingDown_ = false;          // under mutex_: no more starts, exits are final
  std::atomic<bool> stopping_{false};  // the threads end
  std::thread monitor_;
  std::vector<std::thread> heartbeats_;
};

}  // namespace rgnav
