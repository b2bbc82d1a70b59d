// The watchdog's supervision of one server set (see SupervisedSet.h).
#include "watchdog/SupervisedSet.h"

#include <filesystem>
#include <map>

#include "core/common/Errors.h"
#include "watchdog/IsoTime.h"

namespace rgnav {

namespace fs = std::filesystem;
using Clock = SupervisionClock;

namespace {

constexpr auto kMonitorTick = std::chrono::milliseconds(10);
constexpr std::size_t kEventsKept = 2000;

std::string eventLogPath(const SetConfig& config) {
  fs::create_directories(config.runDir + "/logs");
  return config.runDir + "/logs/events.log";
}

ModuleProcessInfo toInfo(const ModuleStatus& m, Clock::time_point now) {
  const double uptime = m.pid ? std::chrono::duration<double>(now - m.startedAt).count() : 0.0;
  return ModuleProcessInfo{m.name, m.state, m.pid, uptime, m.restarts, m.lastEvent};
}

std::map<std::string, PingThreads::Ping> makePings(const SetConfig& config, const ProbeFactory& probes) {
  std::map<std::string, PingThreads::Ping> pings;
  for (const SupervisedModule& m : supervisedModules(config)) pings.emplace(m.spec.name, probes(m.spec, m.endpoint));
  return pings;
}

}  // namespace

SupervisedSet::SupervisedSet(const SetConfig& config, const ProbeFactory& probes)
    : eventLog_(eventLogPath(config), kEventsKept),
      events_(eventLog_),
      processes_(config, events_),
      pings_(makePings(config, probes),
             [this](const std::string& module, bool answered) { onPingResult(module, answered); }),
      supervisor_(config, processes_, pings_, events_) {}

SupervisedSet::~SupervisedSet() { stopThreads(); }

void SupervisedSet::start() {
  std::lock_guard lock(mutex_);
  std::vector<ProcessRecord> left;
  try {
    left = processes_.readState();
  } catch (const Error& e) {
    events_.record("-", "state-unreadable", e.what());
  }
  supervisor_.adopt(left, Clock::now());
  processes_.saveState();
  monitor_ = std::thread([this] { monitor(); });
}

void SupervisedSet::monitor() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    try {
      supervisor_.tick(Clock::now());
    } catch (const std::exception& e) {
      events_.record("-", "supervision-error", e.what());  // supervision goes on
    }
    wake_.wait_for(lock, kMonitorTick, [&] { return stopping_.load() || woken_; });
    woken_ = false;
  }
}

void SupervisedSet::wake() {
  woken_ = true;
  wake_.notify_all();
}

void SupervisedSet::onPingResult(const std::string& module, bool answered) {
  std::lock_guard lock(mutex_);
  if (stopping_) return;
  supervisor_.onPingResult(module, answered, Clock::now());
  wake();  // a second ping after a miss goes out at once
}

void SupervisedSet::stopAll() {
  {
    std::unique_lock lock(mutex_);
    supervisor_.shutDown(Clock::now());
    // The monitor reaps the exits and stops the next module.
    while (!supervisor_.shutDownComplete()) wake_.wait_for(lock, kMonitorTick);
    processes_.saveState();
  }
  stopThreads();
}

void SupervisedSet::stopThreads() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (monitor_.joinable()) monitor_.join();
  pings_.stop();
}

std::vector<ModuleProcessInfo> SupervisedSet::modules() const {
  std::lock_guard lock(mutex_);
  const Clock::time_point now = Clock::now();
  std::vector<ModuleProcessInfo> out;
  for (const ModuleStatus& m : supervisor_.modules()) out.push_back(toInfo(m, now));
  return out;
}

ModuleProcessInfo SupervisedSet::describe(const std::string& name) const {
  std::lock_guard lock(mutex_);
  return toInfo(supervisor_.status(name), Clock::now());
}

void SupervisedSet::stopModule(const std::string& name) {
  std::lock_guard lock(mutex_);
  supervisor_.stopModule(name, Clock::now());
  wake();
}

void SupervisedSet::startModule(const std::string& name) {
  std::lock_guard lock(mutex_);
  supervisor_.startModule(name, Clock::now());
  wake();
}

void SupervisedSet::restartModule(const std::string& name) {
  std::lock_guard lock(mutex_);
  supervisor_.restartModule(name, Clock::now());
  wake();
}

std::vector<SupervisionEvent> SupervisedSet::eventsSince(std::uint64_t afterId, std::size_t maxCount) const {
  std::vector<SupervisionEvent> out;
  for (const Event& e : eventLog_.since(afterId).events) {
    if (out.size() == maxCount) break;
    out.push_back(SupervisionEvent{e.id, formatIsoUtcMillis(e.time), e.module, e.event, e.detail});
  }
  return out;
}

}  // namespace rgnav
