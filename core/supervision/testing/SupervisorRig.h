// Test rig for Supervisor: a process table in memory, a probe whose pings the test answers by
// hand, a list of events and a clock that only moves when the test says so. Every step is a
// plain function call, so the tests are deterministic and take no wall-clock time.
#pragma once

#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/common/Errors.h"
#include "core/supervision/Supervisor.h"

namespace rgnav::testing {

// Processes by module name, plus the processes "on the machine" that a watchdog could adopt.
class FakeProcesses : public ModuleProcesses {
 public:
  pid_t start(const std::string& module) override {
    if (failing.count(module)) throw Error("cannot exec 'rgnav-" + module + "': No such file or directory");
    const pid_t pid = nextPid++;
    table[module] = pid;
    actions.push_back("start " + module);
    return pid;
  }
  std::optional<std::chrono::nanoseconds> adopt(const ProcessRecord& record) override {
    const auto it = machine.find(record.pid);
    if (it == machine.end() || it->second != record.startTime) return std::nullopt;
    table[record.module] = record.pid;
    actions.push_back("adopt " + record.module);
    return adoptedAge;
  }
  void kill(const std::string& module) override { actions.push_back("kill " + module); }
  void requestStop(const std::string& module, SupervisionClock::time_point, std::chrono::nanoseconds) override {
    actions.push_back("stop " + module);
  }
  std::vector<ModuleExit> reap(SupervisionClock::time_point) override { return std::exchange(ended, {}); }

  // The module's process ends; the next reap reports it.
  void exit(const std::string& module, ExitStatus status) {
    ended.push_back({module, table.at(module), status});
    table.erase(module);
  }
  std::size_t count(const std::string& action) const {
    return static_cast<std::size_t>(std::count(actions.begin(), actions.end(), action));
  }

  std::map<std::string, pid_t> table;             // live processes by module
  std::map<pid_t, std::uint64_t> machine;         // adoptable processes: PID -> start time
  std::set<std::string> failing;                  // modules whose start throws
  std::chrono::nanoseconds adoptedAge{0};         // how long an adoptable process has run
  std::vector<std::string> actions;               // "start A", "adopt A", "kill A", "stop A"
  std::vector<ModuleExit> ended;
  pid_t nextPid = 100;
};

class FakeProbe : public LivenessProbe {
 public:
  void ping(const std::string& module, pid_t) override { outstanding.push_back(module); }
  // Whether a ping of the module waits for its answer; takes it off the list.
  bool take(const std::string& module) {
    const auto it = std::find(outstanding.begin(), outstanding.end(), module);
    if (it == outstanding.end()) return false;
    outstanding.erase(it);
    return true;
  }
  std::vector<std::string> outstanding;
};

class RecordedEvents : public SupervisionEvents {
 public:
  void record(const std::string& module, const std::string& what, const std::string&) override {
    events.push_back(module + " " + what);
  }
  std::size_t count(const std::string& event) const {
    return static_cast<std::size_t>(std::count(events.begin(), events.end(), event));
  }
  std::vector<std::string> events;  // "<module> <what>"
};

inline ModuleSpec moduleSpec(const std::string& name, std::vector<std::string> after = {}) {
  ModuleSpec m;
  m.name = name;
  m.command = {"rgnav-" + name};
  m.port = 9000;
  m.objects = {name};
  m.after = std::move(after);
  return m;
}

// A set without a managed naming service; the test adds modules, then calls build().
struct SupervisorRig {
  SupervisorRig() {
    config.name = "test";
    config.host = "127.0.0.1";
    config.naming = {"127.0.0.1", 2809, false};
  }

  void build() { supervisor = std::make_unique<Supervisor>(config, processes, probe, events); }
  void tick() { supervisor->tick(now); }
  void advance(std::chrono::nanoseconds d) {
    now += d;
    tick();
  }
  // Answers the module's outstanding ping; fails the test if there is none.
  void answer(const std::string& module, bool answered) {
    if (!probe.take(module)) throw Error("no ping of " + module + " outstanding");
    supervisor->onPingResult(module, answered, now);
  }
  // Starts every module and answers their first pings, in start order.
  void bringUp() {
    tick();
    for (const ModuleSpec& m : config.modules) {
      answer(m.name, true);
      tick();
    }
  }
  ProcessState state(const std::string& module) const { return supervisor->status(module).state; }

  SetConfig config;
  FakeProcesses processes;
  FakeProbe probe;
  RecordedEvents events;
  SupervisionClock::time_point now{};
  std::unique_ptr<Supervisor> supervisor;
};

}  // namespace rgnav::testing
