// rgnav-ctl: talks to the watchdog of a server set: status table, waiting until every module
// runs, operator stop/start/restart of one module, the event log, and shutdown of the set.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

#include "clientlibs/watchdog/WatchdogClient.h"
#include "watchdog/SetLoading.h"
#include "tools/common/CommandLine.h"
#include "tools/common/ToolClient.h"

namespace po = boost::program_options;

namespace {

constexpr std::uint32_t kEventBatch = 500;  // events asked per call (the watchdog caps a batch)

void printStatus(const std::vector<rgnav::ModuleProcessInfo>& modules) {
  std::printf("%-18s %-9s %8s %10s %8s  %s\n", "MODULE", "STATE", "PID", "UPTIME_S", "RESTARTS", "LAST EVENT");
  for (const auto& m : modules)
    std::printf("%-18s %-9s %8lld %10.1f %8u  %s\n", m.name.c_str(), rgnav::toString(m.state),
                static_cast<long long>(m.pid), m.uptimeSeconds, m.restarts, m.lastEvent.c_str());
}

// Waits until every module runs; false (and the reason on stderr) if one is FATAL or time is up.
bool waitRunning(rgnav::WatchdogClient& watchdog, double timeoutSeconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
  for (;;) {
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
  po::options_description desc(
      "rgnav-ctl --set FILE <status|wait-running|stop M|start M|restart M|events|shutdown|naming>");
  desc.add_options()
      ("help", "this text")
      ("set", po::value(&setFile)->required(), "server set file")
      ("command", po::value(&command)->required(), "what to do")
      ("module", po::value(&module)->default_value(""), "module for stop/start/restart")
      ("timeout", po::value(&timeout)->default_value(30), "seconds, for wait-running")
      ("after", po::value(&after)->default_value(0), "event ID, for events");
  po::positional_options_description positional;
  positional.add("command", 1).add("module", 1);
  try {
    if (!rgnav::parseCommandLine(argc, argv, desc, positional)) return 0;
    const rgnav::SetConfig set = rgnav::loadSet(setFile, rgnav::defaultProjectRoot());
    if (command == "naming") {
      std::cout << set.naming.host << ":" << set.naming.port << std::endl;
      return 0;
    }
    rgnav::ClientSettings settings = rgnav::ClientSettings::fromEnvironment();
    settings.namingHost = set.naming.host;
    settings.namingPort = set.naming.port;
    settings.retryBudget = std::chrono::milliseconds(static_cast<long>(timeout * 1000));
    // wait-running waits for a watchdog that may still be starting; the rest answer at once.
    if (command != "wait-running") settings.firstContactBudget = rgnav::kToolFirstContactBudget;
    rgnav::WatchdogClient watchdog({set.host, set.watchdog.port}, settings);
    if (command == "status") printStatus(watchdog.modules());
    else if (command == "wait-running") return waitRunning(watchdog, timeout) ? 0 : 1;
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
