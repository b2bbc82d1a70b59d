// rgnav-ctl: talks to the watchdog of a server set: status table (where a running module reports
// itself degraded, DEGRADED with its reason: DegradedModules.h), waiting until every module
// runs, operator stop/start/restart of one module, the event log, and shutdown of the set. It
// first checks from /proc that the watchdog can answer (WatchdogReach.h), so a set that is not
// up, a stopped watchdog or a port clash is said at once. Without a watchdog it finds the set's
// modules from the state file (SetLeftovers.h): `status` lists them, `stop-leftovers` stops them,
// and `check-ports` refuses a start while the set's ports are held, naming who holds them.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

#include "clientlibs/watchdog/WatchdogClient.h"
#include "tools/common/CommandLine.h"
#include "tools/common/StrictArguments.h"
#include "tools/common/ToolClient.h"
#include "tools/ctl/DegradedModules.h"
#include "tools/ctl/WatchdogReach.h"
#include "watchdog/ProcStat.h"
#include "watchdog/SetLeftovers.h"
#include "watchdog/SetLoading.h"

namespace po = boost::program_options;

namespace {

constexpr std::uint32_t kEventBatch = 500;  // events asked per call (the watchdog caps a batch)
constexpr auto kCallBudget = std::chrono::milliseconds(2000);  // a watchdog that runs answers at once
constexpr int kNotReachable = 3;  // exit code: the watchdog cannot answer (not up, stopped, clash)

// A degraded module (DegradedModules.h) shows DEGRADED with its reason as its last event.
void printStatus(const std::vector<rgnav::ModuleProcessInfo>& modules,
                 const std::map<std::string, std::string>& degraded = {}) {
  std::printf("%-18s %-9s %8s %10s %8s  %s\n", "MODULE", "STATE", "PID", "UPTIME_S", "RESTARTS", "LAST EVENT");
  for (const auto& m : modules) {
    const auto reason = degraded.find(m.name);
    const bool isDegraded = reason != degraded.end();
    std::printf("%-18s %-9s %8lld %10.1f %8u  %s\n", m.name.c_str(), isDegraded ? "DEGRADED" : rgnav::toString(m.state),
                static_cast<long long>(m.pid), m.uptimeSeconds, m.restarts,
                (isDegraded ? reason->second : m.lastEvent).c_str());
  }
}

// The modules a watchdog that is gone left running, as the state file names them.
void printLeftovers(const std::vector<rgnav::LeftoverModule>& leftovers) {
  std::printf("%-18s %-9s %8s %10s  %s\n", "MODULE", "STATE", "PID", "UPTIME_S", "NOTE");
  for (const auto& m : leftovers)
    std::printf("%-18s %-9s %8lld %10.1f  %s\n", m.record.module.c_str(), "LEFTOVER",
                static_cast<long long>(m.record.pid), std::chrono::duration<double>(m.age).count(),
                "runs without a watchdog");
}

// "" if the set's watchdog can be called; else what is wrong, with the modules it left running.
std::string unreachable(const rgnav::SetConfig& set, std::optional<pid_t> watchdogPid) {
  const rgnav::WatchdogCheck check = rgnav::checkWatchdog(set, watchdogPid);
  if (check.reach != rgnav::WatchdogReach::NotListening) return check.message;
  const auto leftovers = rgnav::leftoverModules(set);
  if (leftovers.empty()) return check.message;
  printLeftovers(leftovers);
  return check.message + "; " + std::to_string(leftovers.size()) +
         " of its modules still run (`rgctl down " + set.name + "` stops them)";
}

// 0 if no port of the set is held (but by the modules the state file names, which a new watchdog
// adopts); else names each port and its holder.
int checkPorts(const rgnav::SetConfig& set) {
  const auto held = rgnav::heldPorts(set, rgnav::leftoverModules(set));
  for (const auto& h : held)
    std::cerr << "rgnav-ctl: set '" << set.name << "' cannot start: port " << h.port << " (its " << h.user
              << ") is held by "
              << (h.holder.pid ? "pid " + std::to_string(h.holder.pid) + " (" + h.holder.command + ")"
                               : std::string("a process of another user"))
              << std::endl;
  if (held.empty()) return 0;
  std::cerr << "rgnav-ctl: stop those processes (kill <pid>) or give the set other ports" << std::endl;
  return kNotReachable;
}

// Stops the modules a watchdog that is gone left running (none: the set is not up).
int stopLeftoverModules(const rgnav::SetConfig& set) {
  const auto leftovers = rgnav::leftoverModules(set);
  if (leftovers.empty()) {
    std::cout << "rgnav-ctl: set '" << set.name << "' is not up" << std::endl;
    return 0;
  }
  std::cout << "rgnav-ctl: set '" << set.name << "' has no watchdog; stopping the " << leftovers.size()
            << " modules it left running:";
  for (const auto& m : leftovers) std::cout << " " << m.record.module << " (pid " << m.record.pid << ")";
  std::cout << std::endl;
  rgnav::stopLeftovers(set, leftovers);
  std::cout << "rgnav-ctl: set '" << set.name << "' down" << std::endl;
  return 0;
}

bool isGone(pid_t pid) {
  const std::optional<rgnav::ProcStat> stat = rgnav::readProcStat(pid);
  return !stat || stat->state == 'Z' || stat->state == 'X';
}

// Waits until every module runs; false (and the reason on stderr) if one is FATAL, the watchdog
// cannot answer (exited, stopped, another process holds its port) or time is up.
bool waitRunning(const rgnav::SetConfig& set, std::optional<pid_t> watchdogPid, rgnav::WatchdogClient& watchdog,
                 double timeoutSeconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
  for (;;) {
    const rgnav::WatchdogCheck check = rgnav::checkWatchdog(set, watchdogPid);
    if (check.reach == rgnav::WatchdogReach::OtherHolder || check.reach == rgnav::WatchdogReach::Stopped) {
      std::cerr << "rgnav-ctl: " << check.message << std::endl;
      return false;
    }
    if (check.reach == rgnav::WatchdogReach::NotListening) {
      if (watchdogPid && isGone(*watchdogPid)) {
        std::cerr << "rgnav-ctl: the watchdog of set '" << set.name << "' (pid " << *watchdogPid
                  << ") exited before it answered; see " << set.runDir << "/logs/watchdog.log" << std::endl;
        return false;
      }
      if (std::chrono::steady_clock::now() > deadline) {
        std::cerr << "rgnav-ctl: " << check.message << " after " << timeoutSeconds << " s" << std::endl;
        return false;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      continue;
    }
    const auto modules = watchdog.modules();
    bool all = true;
    for (const auto& m : modules) {
      if (m.state == rgnav::ProcessState::Fatal) {
        std::cerr << "rgnav-ctl: " << m.name << " is FATAL: " << m.lastEvent << std::endl;
        printStatus(modules);
        return false;
      }
      all &= m.state == rgnav::ProcessState::Running;
    }
    if (all) {
      printStatus(modules);
      return true;
    }
    if (std::chrono::steady_clock::now() > deadline) {
      std::cerr << "rgnav-ctl: not every module runs after " << timeoutSeconds << " s" << std::endl;
      printStatus(modules);
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string setFile, command, module;
  double timeout = 30;
  std::uint64_t after = 0;
  pid_t watchdogPid = 0;
  po::options_description desc(
      "rgnav-ctl --set FILE <status|wait-running|stop M|start M|restart M|events|shutdown|naming|\n"
      "                      check-ports|stop-leftovers>");
  desc.add_options()
      ("help", "this text")
      ("set", po::value(&setFile)->required(), "server set file")
      ("command", po::value(&command)->required(), "what to do")
      ("module", po::value(&module)->default_value(""), "module for stop/start/restart")
      ("timeout", rgnav::strictOption(&timeout, "--timeout")->default_value("30"), "seconds, for wait-running")
      ("after", rgnav::strictOption(&after, "--after")->default_value("0"), "event ID, for events")
      ("watchdog-pid", rgnav::strictOption(&watchdogPid, "--watchdog-pid")->default_value("0"),
       "the set's watchdog (0: the one run_dir/watchdog.pid names); another process on its port is a clash");
  po::positional_options_description positional;
  positional.add("command", 1).add("module", 1);
  try {
    if (!rgnav::parseCommandLine(argc, argv, desc, positional)) return 0;
    const rgnav::SetConfig set = rgnav::loadSet(setFile, rgnav::defaultProjectRoot());
    if (command == "naming") {
      std::cout << set.naming.host << ":" << set.naming.port << std::endl;
      return 0;
    }
    const std::optional<pid_t> expected = watchdogPid > 0 ? std::optional<pid_t>(watchdogPid) : std::nullopt;
    if (command == "check-ports") return checkPorts(set);
    if (command == "stop-leftovers") return stopLeftoverModules(set);
    rgnav::ClientSettings settings = rgnav::ClientSettings::fromEnvironment();
    settings.namingHost = set.naming.host;
    settings.namingPort = set.naming.port;
    settings.retryBudget = command == "wait-running" ? std::chrono::milliseconds(static_cast<long>(timeout * 1000))
                                                     : kCallBudget;
    // wait-running waits for a watchdog that may still be starting; the rest answer at once.
    if (command != "wait-running") settings.firstContactBudget = rgnav::kToolFirstContactBudget;
    rgnav::WatchdogClient watchdog({set.host, set.watchdog.port}, settings);
    if (command == "wait-running") return waitRunning(set, expected, watchdog, timeout) ? 0 : 1;
    if (const std::string why = unreachable(set, expected); !why.empty()) {
      std::cerr << "rgnav-ctl: " << why << std::endl;
      return kNotReachable;
    }
    if (command == "status") {
      const auto modules = watchdog.modules();
      printStatus(modules, rgnav::degradedModules(set, settings, modules));
    }
    else if (command == "stop") watchdog.stopModule(module);
    else if (command == "start") watchdog.startModule(module);
    else if (command == "restart") watchdog.restartModule(module);
    else if (command == "shutdown") watchdog.shutdownSet();
    else if (command == "events") {
      for (auto batch = watchdog.eventsSince(after, kEventBatch); !batch.empty();
           batch = watchdog.eventsSince(batch.back().id, kEventBatch))
        for (const auto& e : batch)
          std::cout << e.time << " " << e.id << " " << e.module << " " << e.what << " " << e.detail << "\n";
    } else {
      std::cerr << "rgnav-ctl: unknown command '" << command << "'\n" << desc << std::endl;
      return 2;
    }
    return 0;
  } catch (const po::error& e) {
    std::cerr << "rgnav-ctl: " << e.what() << "\n" << desc << std::endl;
  } catch (const rgnav::ModuleUnavailableError& e) {
    rgnav::reportUnreachable("rgnav-ctl", e, false);
  } catch (const std::exception& e) {
    std::cerr << "rgnav-ctl: " << e.what() << std::endl;
  }
  return 2;
}
