// The supervision state machine of one server set (see Supervisor.h).
#include "core/supervision/Supervisor.h"

#include <algorithm>

#include "core/common/Errors.h"

namespace rgnav {

using Clock = SupervisionClock;

struct Supervisor::Module {
  explicit Module(SupervisedModule d) : def(std::move(d)), tracker(def.spec.name, def.spec.policy) {}

  const std::string& name() const { return def.spec.name; }

  SupervisedModule def;
  RestartTracker tracker;
  ProcessState state = ProcessState::Stopped;
  bool wanted = true;  // should run: false after an operator stop, StayDown or FATAL
  bool everStarted = false;
  bool operatorStop = false;  // the pending exit was asked for
  bool restartAfterStop = false;
  std::optional<Clock::time_point> restartAt;
  std::optional<Clock::time_point> stopGiveUpAt;  // of a shutdown stop
  Clock::time_point startedAt;  // of the process (an adopted one started before this watchdog)
  Clock::time_point adoptedAt;  // of a process left running by a previous watchdog, else startedAt
  pid_t pid = 0;
  std::uint32_t restarts = 0;
  std::string lastEvent;
  // Heartbeat: one ping at a time, answered for the process that was pinged.
  int misses = 0;
  Clock::time_point nextPingAt;
  bool pingOutstanding = false;
  pid_t pingedPid = 0;
};

Supervisor::Supervisor(const SetConfig& config, ModuleProcesses& processes, LivenessProbe& probe,
                       SupervisionEvents& events)
    : setName_(config.name), watchdog_(config.watchdog), processes_(processes), probe_(probe), events_(events) {
  for (SupervisedModule& m : supervisedModules(config)) modules_.emplace_back(std::move(m));
}

Supervisor::~Supervisor() = default;

Supervisor::Module& Supervisor::find(const std::string& name) {
  for (Module& m : modules_)
    if (m.name() == name) return m;
  throw InvalidArgumentError("no module '" + name + "' in set '" + setName_ + "'");
}

const Supervisor::Module& Supervisor::find(const std::string& name) const {
  return const_cast<Supervisor*>(this)->find(name);
}

void Supervisor::event(Module& module, const std::string& what, const std::string& detail) {
  module.lastEvent = what + (detail.empty() ? "" : ": " + detail);
  events_.record(module.name(), what, detail);
}

void Supervisor::adopt(const std::vector<ProcessRecord>& left, Clock::time_point now) {
  for (const ProcessRecord& record : left) {
    const auto it = std::find_if(modules_.begin(), modules_.end(),
                                 [&](const Module& m) { return m.name() == record.module; });
    if (it == modules_.end() || it->pid != 0) continue;
    const std::optional<std::chrono::nanoseconds> age = processes_.adopt(record);
    if (!age) continue;
    Module& module = *it;
    module.pid = record.pid;
    module.state = ProcessState::Starting;
    module.startedAt = now - *age;  // its uptime is the process's, not the new watchdog's
    module.adoptedAt = now;
    module.nextPingAt = now;
    module.everStarted = true;
    event(module, "adopted", "pid " + std::to_string(record.pid) + " left running by a previous watchdog");
  }
}

void Supervisor::launch(Module& module, Launch kind, Clock::time_point now) {
  static constexpr const char* kWhy[] = {"started", "restarted", "started-by-operator", "restarted-by-operator"};
  const char* why = kWhy[static_cast<int>(kind)];
  module.restartAt.reset();
  module.misses = 0;
  if (shuttingDown_) {
    module.state = ProcessState::Stopped;
    event(module, "not-started", std::string(why) + " refused: the set is shutting down");
    return;
  }
  try {
    module.pid = processes_.start(module.name());
  } catch (const std::exception& e) {
    module.everStarted = true;
    event(module, "spawn-failed", e.what());
    handleExit(module, ExitStatus::notStarted(e.what()), now);
    return;
  }
  module.state = ProcessState::Starting;
  module.startedAt = now;
  module.adoptedAt = now;
  module.nextPingAt = now;  // its heartbeat starts at once
  module.everStarted = true;
  event(module, why, "pid " + std::to_string(module.pid));
}

void Supervisor::handleExit(Module& module, const ExitStatus& status, Clock::time_point now) {
  module.pid = 0;
  if (module.operatorStop) {
    module.operatorStop = false;
    module.state = ProcessState::Stopped;
    event(module, "stopped", status.describe());
    if (module.restartAfterStop) {
      module.restartAfterStop = false;
      module.wanted = true;
      module.tracker.reset();
      module.restarts = 0;
      launch(module, Launch::OperatorRestart, now);
    }
    return;
  }
  if (shuttingDown_) {
    module.state = ProcessState::Stopped;
    event(module, "stopped", status.describe() + " while the set shuts down");
    return;
  }
  const RestartDecision decision = module.tracker.onExit(ExitInfo{status, false}, now);
  switch (decision.action) {
    case RestartDecision::Action::Restart: {
      ++module.restarts;  // counted when decided, as the event says, even if the start then fails
      const double delay = std::chrono::duration<double>(decision.delay).count();
      event(module, "exited",
            status.describe() + (delay > 0 ? "; restart in " + std::to_string(delay) + " s" : "; restarting"));
      if (decision.delay.count() == 0) {
        launch(module, Launch::Restart, now);
      } else {
        module.state = ProcessState::Backoff;
        module.restartAt = now + decision.delay;
      }
      break;
    }
    case RestartDecision::Action::StayDown:
      module.state = ProcessState::Stopped;
      module.wanted = false;
      event(module, "exited", status.describe() + "; " + decision.reason);
      break;
    case RestartDecision::Action::Fatal:
      module.state = ProcessState::Fatal;
      module.wanted = false;
      event(module, "FATAL", decision.reason);
      break;
  }
}

void Supervisor::markHung(Module& module, const std::string& why) {
  module.state = ProcessState::Hung;
  event(module, "hung", why + "; SIGKILL to pid " + std::to_string(module.pid));
  processes_.kill(module.name());
}

void Supervisor::requestStop(Module& module, Clock::time_point now) {
  module.operatorStop = true;
  processes_.requestStop(module.name(), now, module.def.spec.policy.stopTimeout);
}

bool Supervisor::dependenciesReady(const Module& module) const {
  const auto& deps = module.def.dependencies;
  return std::all_of(deps.begin(), deps.end(),
                     [&](const std::string& d) { return find(d).state == ProcessState::Running; });
}

void Supervisor::tick(Clock::time_point now) {
  for (const ModuleExit& exit : processes_.reap(now)) handleExit(find(exit.module), exit.status, now);
  for (Module& module : modules_) {
    if (module.state == ProcessState::Starting && now - module.adoptedAt > module.def.spec.policy.startTimeout)
      markHung(module, "no answer within the start timeout");
    else if (module.state == ProcessState::Backoff && module.restartAt && now >= *module.restartAt)
      launch(module, Launch::Restart, now);
    else if (!module.everStarted && module.wanted && module.pid == 0 && dependenciesReady(module))
      launch(module, Launch::First, now);
  }
  if (shuttingDown_) advanceShutdown(now);
  sendDuePings(now);
}

void Supervisor::sendDuePings(Clock::time_point now) {
  for (Module& module : modules_) {
    const bool pinged = module.state == ProcessState::Starting || module.state == ProcessState::Running;
    if (!pinged || module.pid == 0 || module.pingOutstanding || now < module.nextPingAt) continue;
    module.pingOutstanding = true;
    module.pingedPid = module.pid;
    probe_.ping(module.name(), module.pid);
  }
}

void Supervisor::onPingResult(const std::string& name, bool answered, Clock::time_point now) {
  Module& module = find(name);
  module.pingOutstanding = false;
  if (module.pid == 0 || module.pid != module.pingedPid) return;  // the process changed meanwhile
  bool askAgainAtOnce = false;
  if (answered) {
    module.misses = 0;
    if (module.state == ProcessState::Starting) {
      module.state = ProcessState::Running;
      module.tracker.onReady();
      event(module, "ready", "pid " + std::to_string(module.pid) + " answers");
    }
  } else if (module.state == ProcessState::Running && !shuttingDown_) {
    if (++module.misses >= watchdog_.hangMisses)
      markHung(module, std::to_string(module.misses) + " pings unanswered");
    else
      askAgainAtOnce = true;
  }
  const auto period = module.state == ProcessState::Starting
                          ? std::min<std::chrono::nanoseconds>(watchdog_.heartbeatPeriod, kStartingPingPeriod)
                          : watchdog_.heartbeatPeriod;
  module.nextPingAt = askAgainAtOnce ? now : now + period;
}

void Supervisor::stopModule(const std::string& name, Clock::time_point now) {
  Module& module = find(name);
  module.wanted = false;
  module.restartAt.reset();
  if (module.pid != 0) {
    requestStop(module, now);
    event(module, "stop-requested", "by operator");
  } else if (module.state != ProcessState::Stopped) {
    module.state = ProcessState::Stopped;
    event(module, "stopped", "by operator");
  }
}

void Supervisor::startModule(const std::string& name, Clock::time_point now) {
  Module& module = find(name);
  if (module.pid != 0) return;  // already running
  module.wanted = true;
  module.tracker.reset();
  module.restarts = 0;
  launch(module, Launch::OperatorStart, now);
}

void Supervisor::restartModule(const std::string& name, Clock::time_point now) {
  Module& module = find(name);
  if (module.pid == 0) return startModule(name, now);
  module.restartAfterStop = true;
  requestStop(module, now);
  event(module, "restart-requested", "by operator");
}

void Supervisor::shutDown(Clock::time_point now) {
  shuttingDown_ = true;
  for (Module& module : modules_) {
    module.wanted = false;
    module.restartAfterStop = false;
    module.restartAt.reset();
    if (module.state == ProcessState::Backoff) module.state = ProcessState::Stopped;
  }
  stopsLeft_ = modules_.size();
  advanceShutdown(now);
}

void Supervisor::advanceShutdown(Clock::time_point now) {
  while (stopsLeft_ > 0) {
    Module& module = modules_[stopsLeft_ - 1];
    if (module.pid == 0) {
      --stopsLeft_;
    } else if (!module.stopGiveUpAt) {
      requestStop(module, now);
      module.stopGiveUpAt = now + module.def.spec.policy.stopTimeout + kKillGrace;
      return;
    } else if (now > *module.stopGiveUpAt) {
      event(module, "stop-failed", "pid " + std::to_string(module.pid) + " survived SIGKILL");
      --stopsLeft_;
    } else {
      return;
    }
  }
}

bool Supervisor::shutDownComplete() const { return shuttingDown_ && stopsLeft_ == 0; }

ModuleStatus Supervisor::status(const std::string& name) const {
  const Module& m = find(name);
  return ModuleStatus{m.name(), m.state, m.pid, m.startedAt, m.restarts, m.lastEvent};
}

std::vector<ModuleStatus> Supervisor::modules() const {
  std::vector<ModuleStatus> out;
  for (const Module& m : modules_) out.push_back(status(m.name()));
  return out;
}

}  // namespace rgnav
