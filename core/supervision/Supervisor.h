// Supervisor: the supervision state machine of one server set (thesis ch. 5, the watchdog):
// first start in dependency order (a module starts once its dependencies answer pings),
// heartbeats (hung = hang_misses pings unanswered in a row while running, or no answer within
// start_timeout after a start: the process group gets SIGKILL), exits, restarts decided by
// each module's RestartTracker (Erlang policy, max_restarts in restart_window then FATAL,
// exponential backoff for a module that never answered), operator stop / start / restart of one
// module, adoption of the processes a previous watchdog left running, and an orderly stop in
// reverse start order.
//
// It owns no thread, no clock and no process: the caller passes `now` into every call, and the
// outside world comes in through ModuleProcesses, LivenessProbe and SupervisionEvents. Not
// thread-safe: the watchdog serialises the calls (watchdog/SupervisedSet.h).
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/supervision/LivenessProbe.h"
#include "core/supervision/ModuleProcesses.h"
#include "core/supervision/ProcessRecord.h"
#include "core/supervision/ProcessState.h"
#include "core/supervision/RestartTracker.h"
#include "core/supervision/SetConfig.h"
#include "core/supervision/SupervisedModules.h"
#include "core/supervision/SupervisionEvents.h"

namespace rgnav {

struct ModuleStatus {
  std::string name;
  ProcessState state = ProcessState::Stopped;
  pid_t pid = 0;                          // 0: no process
  SupervisionClock::time_point startedAt;  // of the current process
  // Automatic restarts decided since the watchdog or the operator last started the module (the
  // count the restart and FATAL events give).
  std::uint32_t restarts = 0;
  std::string lastEvent;
};

class Supervisor {
 public:
  // A module in Starting is pinged this often (at most heartbeat_period) until it answers.
  static constexpr std::chrono::milliseconds kStartingPingPeriod{25};

  // Supervises supervisedModules(config); nothing happens before the first adopt or tick.
  Supervisor(const SetConfig& config, ModuleProcesses& processes, LivenessProbe& probe, SupervisionEvents& events);
  ~Supervisor();
  Supervisor(const Supervisor&) = delete;
  Supervisor& operator=(const Supervisor&) = delete;

  // Takes over the processes named in a previous watchdog's state file that still run with the
  // recorded start time; they count as Starting until they answer a ping. Records of unknown
  // modules, dead processes and reused PIDs are ignored: tick() starts those modules anew.
  void adopt(const std::vector<ProcessRecord>& left, SupervisionClock::time_point now);
  // One supervision step: handles the exits reaped since the last tick, hangs on start timeout,
  // restarts whose backoff is over, first starts whose dependencies answer, the next step of a
  // shutdown, and sends the pings that are due.
  void tick(SupervisionClock::time_point now);
  // The outcome of the module's outstanding ping. Ignored if the process changed meanwhile.
  void onPingResult(const std::string& module, bool answered, SupervisionClock::time_point now);

  // Operator control; InvalidArgumentError for a module the set does not have.
  void stopModule(const std::string& module, SupervisionClock::time_point now);
  void startModule(const std::string& module, SupervisionClock::time_point now);
  void restartModule(const std::string& module, SupervisionClock::time_point now);

  // Stops every module in reverse start order, one after the other (each gets its stop timeout,
  // then SIGKILL, then kKillGrace before it is given up); nothing is started or restarted any
  // more. tick() carries it on until shutDownComplete().
  void shutDown(SupervisionClock::time_point now);
  bool shutDownComplete() const;

  std::vector<ModuleStatus> modules() const;
  // InvalidArgumentError for a module the set does not have.
  ModuleStatus status(const std::string& module) const;

 private:
  struct Module;
  enum class Launch { First, Restart, OperatorStart, OperatorRestart };

  Module& find(const std::string& name);
  const Module& find(const std::string& name) const;
  void launch(Module& module, Launch kind, SupervisionClock::time_point now);
  void handleExit(Module& module, const ExitStatus& status, SupervisionClock::time_point now);
  void markHung(Module& module, const std::string& why);
  void requestStop(Module& module, SupervisionClock::time_point now);
  bool dependenciesReady(const Module& module) const;
  void advanceShutdown(SupervisionClock::time_point now);
  void sendDuePings(SupervisionClock::time_point now);
  void event(Module& module, const std::string& what, const std::string& detail);

  std::string setName_;
  WatchdogConfig watchdog_;
  ModuleProcesses& processes_;
  LivenessProbe& probe_;
  SupervisionEvents& events_;
  std::vector<Module> modules_;  // start order
  bool shuttingDown_ = false;    // no more starts, exits are final
  std::size_t stopsLeft_ = 0;    // during shutdown: modules_[0, stopsLeft_) are still to stop
};

}  // namespace rgnav
