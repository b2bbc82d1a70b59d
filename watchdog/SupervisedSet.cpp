// Supervision of one server set (see SupervisedSet.h).
#include "watchdog/SupervisedSet.h"

#include <signal.h>

#include <algorithm>
#include <filesystem>

#include "core/common/Errors.h"
#include "core/supervision/StartOrder.h"
#include "watchdog/IsoTime.h"

namespace rgnav {

namespace fs = std::filesystem;
using Clock = SupervisionClock;

namespace {
constexpr auto kMonitorTick = std::chrono::milliseconds(10);
constexpr auto kStartingPingPeriod = std::chrono::milliseconds(25);
constexpr std::size_t kEventsKept = 2000;
}  // namespace

struct SupervisedSet::Module {
  Module(ModuleSpec s, HostPort e) : spec(std::move(s)), endpoint(std::move(e)), tracker(spec.name, spec.policy) {}

  ModuleSpec spec;
  HostPort endpoint;
  RestartTracker tracker;
  ProcessState state = ProcessState::Stopped;
  bool wanted = true;            // should run: false after an operator stop, StayDown or FATAL
  bool everStarted = false;
  bool operatorStop = false;     // the pending exit was asked for
  bool restartAfterStop = false;
  std::optional<Clock::time_point> restartAt;
  Clock::time_point startedAt;
  pid_t pid = 0;
  int misses = 0;
  std::uint32_t restarts = 0;
  std::string lastEvent;
  std::function<bool()> probe;
};

SupervisedSet::SupervisedSet(SetConfig config, ProbeFactory probes)
    : config_(std::move(config)),
      probes_(std::move(probes)),
      events_((fs::create_directories(config_.runDir + "/logs"), config_.runDir + "/logs/events.log"), kEventsKept),
      stateFile_(config_.runDir + "/watchdog.state") {
  if (config_.naming.managed) {
    ModuleSpec naming;
    naming.name = kNamingModule;
    naming.command = {"omniNames"};
    naming.port = config_.naming.port;
    naming.objects = {kNamingModule};
    naming.policy = config_.defaults;
    modules_.push_back(std::make_unique<Module>(naming, HostPort{config_.naming.host, config_.naming.port}));
  }
  for (const std::string& name : startOrder(config_.modules)) {
    const auto& spec = *std::find_if(config_.modules.begin(), config_.modules.end(),
                                     [&](const ModuleSpec& m) { return m.name == name; });
    modules_.push_back(std::make_unique<Module>(spec, HostPort{config_.host, spec.port}));
  }
  for (auto& module : modules_) module->probe = probes_(module->spec, module->endpoint);
}

SupervisedSet::~SupervisedSet() {
  {
    std::lock_guard lock(mutex_);
    shuttingDown_ = true;
    stopping_ = true;
  }
  wake_.notify_all();
  joinThreads();
}

void SupervisedSet::event(Module& module, const std::string& what, const std::string& detail) {
  module.lastEvent = what + (detail.empty() ? "" : ": " + detail);
  record(module.spec.name, what, detail);
}

void SupervisedSet::record(const std::string& module, const std::string& what, const std::string& detail) {
  try {
    events_.record(module, what, detail);
  } catch (const Error&) {
    // The event stays in memory; a full disk must not stop supervision.
  }
}

SupervisedSet::Module& SupervisedSet::find(const std::string& name) {
  for (auto& m : modules_)
    if (m->spec.name == name) return *m;
  throw InvalidArgumentError("no module '" + name + "' in set '" + config_.name + "'");
}

const SupervisedSet::Module& SupervisedSet::find(const std::string& name) const {
  return const_cast<SupervisedSet*>(this)->find(name);
}

void SupervisedSet::start() {
  std::lock_guard lock(mutex_);
  std::vector<ProcessRecord> left;
  try {
    left = stateFile_.read();
  } catch (const Error& e) {
    record("-", "state-unreadable", e.what());
  }
  for (const ProcessRecord& record : left) {
    auto it = std::find_if(modules_.begin(), modules_.end(), [&](auto& m) { return m->spec.name == record.module; });
    if (it == modules_.end() || !processes_.adopt(record)) continue;
    Module& module = **it;
    module.pid = record.pid;
    module.state = ProcessState::Starting;
    module.startedAt = Clock::now();
    module.everStarted = true;
    event(module, "adopted", "pid " + std::to_string(record.pid) + " left running by a previous watchdog");
  }
  saveState();
  monitor_ = std::thread([this] { monitor(); });
  for (auto& module : modules_) heartbeats_.emplace_back([this, m = module.get()] { heartbeat(*m); });
}

SpawnSpec SupervisedSet::spawnSpec(const Module& module) const {
  SpawnSpec spec;
  spec.logFile = config_.runDir + "/logs/" + module.spec.name + ".log";
  spec.env = module.spec.env;
  if (module.spec.name == kNamingModule) {
    const std::string dataDir = config_.runDir + "/naming";
    fs::create_directories(dataDir);
    bool hasData = false;
    for (const auto& entry : fs::directory_iterator(dataDir))
      hasData |= entry.path().filename().string().starts_with("omninames-") && entry.path().extension() == ".dat";
    spec.argv = {"omniNames", "-logdir", dataDir, "-ORBendPoint", "giop:tcp:" + module.endpoint.str()};
    if (!hasData) spec.argv.insert(spec.argv.end(), {"-start", std::to_string(module.endpoint.port)});
    return spec;
  }
  const std::string stateDir = config_.runDir + "/state/" + module.spec.name;
  spec.argv = module.spec.command;
  spec.argv.insert(spec.argv.end(), {"--module", module.spec.name, "--robot", config_.robot, "--endpoint",
                                     module.endpoint.str(), "--naming",
                                     HostPort{config_.naming.host, config_.naming.port}.str(), "--state-dir", stateDir});
  return spec;
}

void SupervisedSet::launch(Module& module, Launch kind) {
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
    module.pid = processes_.start(module.spec.name, spawnSpec(module)).pid();
  } catch (const std::exception& e) {
    module.everStarted = true;
    event(module, "spawn-failed", e.what());
    handleExit(module, ExitStatus::exited(127));
    return;
  }
  module.state = ProcessState::Starting;
  module.startedAt = Clock::now();
  if (kind == Launch::Restart) ++module.restarts;
  module.everStarted = true;
  event(module, why, "pid " + std::to_string(module.pid));
  saveState();
  wake_.notify_all();  // its heartbeat starts probing at once
}

void SupervisedSet::handleExit(Module& module, const ExitStatus& status) {
  module.pid = 0;
  saveState();
  if (module.operatorStop) {
    module.operatorStop = false;
    module.state = ProcessState::Stopped;
    event(module, "stopped", status.describe());
    if (module.restartAfterStop) {
      module.restartAfterStop = false;
      module.wanted = true;
      module.tracker.reset();
      launch(module, Launch::OperatorRestart);
    }
    return;
  }
  if (shuttingDown_) {
    module.state = ProcessState::Stopped;
    event(module, "stopped", status.describe() + " while the set shuts down");
    return;
  }
  const RestartDecision decision = module.tracker.onExit(ExitInfo{status, false}, Clock::now());
  switch (decision.action) {
    case RestartDecision::Action::Restart:
      event(module, "exited", status.describe() + (decision.delay.count() ? "; restart in " +
                                                       std::to_string(std::chrono::duration<double>(decision.delay).count()) + " s"
                                                                        : "; restarting"));
      if (decision.delay.count() == 0) {
        launch(module, Launch::Restart);
      } else {
        module.state = ProcessState::Backoff;
        module.restartAt = Clock::now() + decision.delay;
      }
      break;
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

void SupervisedSet::markHung(Module& module, const std::string& why) {
  module.state = ProcessState::Hung;
  event(module, "hung", why + "; SIGKILL to pid " + std::to_string(module.pid));
  if (ChildProcess* child = processes_.find(module.spec.name)) child->signalGroup(SIGKILL);
}

bool SupervisedSet::dependenciesReady(const Module& module) const {
  std::vector<std::string> deps = module.spec.after;
  if (config_.naming.managed && module.spec.name != kNamingModule) deps.push_back(kNamingModule);
  return std::all_of(deps.begin(), deps.end(), [&](const std::string& d) { return find(d).state == ProcessState::Running; });
}

void SupervisedSet::saveState() {
  try {
    stateFile_.write(processes_.records());
  } catch (const Error& e) {
    record("-", "state-unwritable", e.what());
  }
}

void SupervisedSet::superviseOnce(Clock::time_point now) {
  for (const ModuleExit& exit : processes_.poll(now)) handleExit(find(exit.module), exit.status);
  for (auto& m : modules_) {
    Module& module = *m;
    if (module.state == ProcessState::Starting && now - module.startedAt > module.spec.policy.startTimeout)
      markHung(module, "no answer within the start timeout");
    else if (module.state == ProcessState::Backoff && module.restartAt && now >= *module.restartAt)
      launch(module, Launch::Restart);
    else if (!module.everStarted && module.wanted && module.pid == 0 && dependenciesReady(module))
      launch(module, Launch::First);
  }
}

void SupervisedSet::monitor() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    try {
      superviseOnce(Clock::now());
    } catch (const std::exception& e) {
      record("-", "supervision-error", e.what());  // supervision goes on
    }
    wake_.wait_for(lock, kMonitorTick, [&] { return stopping_.load(); });
  }
}

void SupervisedSet::heartbeat(Module& module) {
  const auto period = config_.watchdog.heartbeatPeriod;
  std::unique_lock lock(mutex_);
  bool retryAtOnce = false;
  while (!stopping_) {
    if (!retryAtOnce) {
      const auto wait = module.state == ProcessState::Starting
                            ? std::min<std::chrono::nanoseconds>(period, kStartingPingPeriod)
                            : period;
      const pid_t before = module.pid;
      wake_.wait_for(lock, wait, [&] { return stopping_.load() || module.pid != before; });
    }
    retryAtOnce = false;
    if (stopping_) break;
    if (module.state != ProcessState::Starting && module.state != ProcessState::Running) continue;
    const pid_t pinged = module.pid;
    lock.unlock();
    const bool ok = module.probe();
    lock.lock();
    if (module.pid != pinged || pinged == 0) continue;  // the process changed meanwhile
    if (ok) {
      module.misses = 0;
      if (module.state == ProcessState::Starting) {
        module.state = ProcessState::Running;
        module.tracker.onReady();
        event(module, "ready", "pid " + std::to_string(module.pid) + " answers");
      }
    } else if (module.state == ProcessState::Running && !shuttingDown_) {
      if (++module.misses >= config_.watchdog.hangMisses)
        markHung(module, std::to_string(module.misses) + " pings unanswered");
      else
        retryAtOnce = true;
    }
  }
}

void SupervisedSet::stopAll() {
  {
    std::lock_guard lock(mutex_);
    shuttingDown_ = true;
    for (auto& module : modules_) {
      module->wanted = false;
      module->restartAfterStop = false;
      module->restartAt.reset();
      if (module->state == ProcessState::Backoff) module->state = ProcessState::Stopped;
    }
  }
  for (auto it = modules_.rbegin(); it != modules_.rend(); ++it) stopAndWait(**it);
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    saveState();
  }
  wake_.notify_all();
  joinThreads();
}

void SupervisedSet::stopAndWait(Module& module) {
  const auto giveUp = Clock::now() + module.spec.policy.stopTimeout + ChildProcess::kKillGrace;
  std::unique_lock lock(mutex_);
  ChildProcess* child = processes_.find(module.spec.name);
  if (!child) return;
  module.operatorStop = true;
  child->requestStop(Clock::now(), module.spec.policy.stopTimeout);
  // The monitor thread reaps it (and sends SIGKILL after the stop timeout).
  while (processes_.find(module.spec.name)) {
    if (Clock::now() > giveUp) {
      event(module, "stop-failed", "pid " + std::to_string(module.pid) + " survived SIGKILL");
      return;
    }
    wake_.wait_for(lock, kMonitorTick);
  }
}

void SupervisedSet::joinThreads() {
  if (monitor_.joinable()) monitor_.join();
  for (auto& t : heartbeats_)
    if (t.joinable()) t.join();
}

std::vector<ModuleProcessInfo> SupervisedSet::modules() const {
  std::vector<ModuleProcessInfo> out;
  for (const auto& m : modules_) out.push_back(describe(m->spec.name));
  return out;
}

ModuleProcessInfo SupervisedSet::describe(const std::string& name) const {
  std::lock_guard lock(mutex_);
  const Module& module = find(name);
  const double uptime =
      module.pid ? std::chrono::duration<double>(Clock::now() - module.startedAt).count() : 0.0;
  return ModuleProcessInfo{module.spec.name, module.state, module.pid, uptime, module.restarts, module.lastEvent};
}

void SupervisedSet::stopModule(const std::string& name) {
  std::lock_guard lock(mutex_);
  Module& module = find(name);
  module.wanted = false;
  module.restartAt.reset();
  if (ChildProcess* child = processes_.find(name)) {
    module.operatorStop = true;
    child->requestStop(Clock::now(), module.spec.policy.stopTimeout);
    event(module, "stop-requested", "by operator");
  } else if (module.state != ProcessState::Stopped) {
    module.state = ProcessState::Stopped;
    event(module, "stopped", "by operator");
  }
}

void SupervisedSet::startModule(const std::string& name) {
  std::lock_guard lock(mutex_);
  Module& module = find(name);
  if (processes_.find(name)) return;  // already running
  module.wanted = true;
  module.tracker.reset();
  launch(module, Launch::OperatorStart);
}

void SupervisedSet::restartModule(const std::string& name) {
  std::lock_guard lock(mutex_);
  Module& module = find(name);
  if (ChildProcess* child = processes_.find(name)) {
    module.operatorStop = true;
    module.restartAfterStop = true;
    child->requestStop(Clock::now(), module.spec.policy.stopTimeout);
    event(module, "restart-requested", "by operator");
  } else {
    module.wanted = true;
    module.tracker.reset();
    launch(module, Launch::OperatorStart);
  }
}

std::vector<SupervisionEvent> SupervisedSet::eventsSince(std::uint64_t afterId, std::size_t maxCount) const {
  std::vector<SupervisionEvent> out;
  for (const Event& e : events_.since(afterId).events) {
    if (out.size() == maxCount) break;
    out.push_back(SupervisionEvent{e.id, formatIsoUtcMillis(e.time), e.module, e.event, e.detail});
  }
  return out;
}

}  // namespace rgnav
