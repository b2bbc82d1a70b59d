// SupervisedSet: the watchdog's supervision of one server set. The decisions are the
// Supervisor's (core/supervision/Supervisor.h: dependency order, heartbeats and hangs,
// restarts, FATAL, backoff, adoption, orderly stop); this class wires it to the real world:
// processes by fork/exec and waitpid (SetProcesses), pings on one thread per module
// (PingThreads), the event log (run_dir/logs/events.log), a monitor thread that steps the
// Supervisor every 10 ms, and one lock that serialises it all.
//
// If the watchdog itself dies, the modules keep running: they lead their own process groups.
// The state file (run_dir/watchdog.state) names each module's PID and start time; a restarted
// watchdog adopts the live ones (watching them by heartbeat and /proc, since they are no longer
// its children) and starts only what is missing.
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "clientlibs/watchdog/WatchdogTypes.h"
#include "core/common/HostPort.h"
#include "core/supervision/Supervisor.h"
#include "watchdog/EventLog.h"
#include "watchdog/EventLogSink.h"
#include "watchdog/PingThreads.h"
#include "watchdog/SetProcesses.h"

namespace rgnav {

// Answers whether one module's process (the PID it is given) is alive; made once per module and
// called on its ping thread.
using ProbeFactory = std::function<PingThreads::Ping(const ModuleSpec& module, const HostPort& endpoint)>;

class SupervisedSet {
 public:
  SupervisedSet(const SetConfig& config, const ProbeFactory& probes);
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
  void monitor();
  void onPingResult(const std::string& module, bool answered);
  void wake();  // under lock: the monitor steps at once
  void stopThreads();

  EventLog eventLog_;
  EventLogSink events_;
  SetProcesses processes_;
  PingThreads pings_;

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool woken_ = false;                 // under mutex_
  std::atomic<bool> stopping_{false};  // the threads end
  Supervisor supervisor_;              // under mutex_
  std::thread monitor_;
};

}  // namespace rgnav
