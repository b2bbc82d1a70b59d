// TestCluster: a real server set for integration tests, fault tests and benchmarks: a temporary
// directory, free loopback ports, a generated set file, and a real rgnav-watchdog (which runs
// omniNames and the modules). Teardown always happens: the set is shut down, every process seen
// is killed by PID if still alive (never by name), and the directory is removed. The watchdog
// also gets SIGTERM if the harness process dies.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "clientlibs/common/ClientSettings.h"
#include "clientlibs/watchdog/WatchdogClient.h"

namespace rgnav::testing {

struct ClusterModule {
  std::string name;
  std::vector<std::string> command;  // the module's own arguments; the watchdog adds the rest
  std::vector<std::string> objects;
  std::vector<std::string> after = {};
  std::string policyYaml = {};       // extra per-module keys, e.g. "max_restarts: 3"
};

// One host's part: the set's name, the address its servers publish (any 127.x.y.z is a host of
// its own on loopback), and whether it runs the naming service or uses another host's.
struct ClusterHost {
  std::string name = "cluster";
  std::string address = "127.0.0.1";
  int externalNamingPort = 0;  // 0: this host's watchdog runs omniNames on 127.0.0.1
};

class TestCluster {
 public:
  // setYaml: extra top-level YAML (e.g. a "defaults:" block).
  TestCluster(std::vector<ClusterModule> modules, std::string setYaml = "", ClusterHost host = {});
  ~TestCluster();
  TestCluster(const TestCluster&) = delete;
  TestCluster& operator=(const TestCluster&) = delete;

  // Starts the watchdog and waits until every module named in `running` runs (all if empty).
  void start(const std::vector<std::string>& running = {});
  // Stops the watchdog with a signal and waits for it to end (SIGKILL leaves modules running).
  void stopWatchdog(int signal);

  WatchdogClient& watchdog();
  ClientSettings clientSettings() const;
  const std::string& dir() const { return dir_; }
  const std::string& setFile() const { return setFile_; }
  int namingPort() const { return namingPort_; }
  int watchdogPort() const { return watchdogPort_; }
  int modulePort(const std::string& name) const { return ports_.at(name); }

  // Current state of one module; remembers its PID for the final cleanup.
  ModuleProcessInfo describe(const std::string& name);
  // Waits (polling) until pred holds for the module; throws std::runtime_error after `limit`
  // and InterruptedError (Interruption.h) when the program caught a termination signal.
  ModuleProcessInfo waitFor(const std::string& name, const std::function<bool(const ModuleProcessInfo&)>& pred,
                            const std::string& what, std::chrono::milliseconds limit = std::chrono::seconds(20));

  // Absolute path of a program built by the project / of a file in the shared data folder.
  static std::string program(const std::string& name);
  static std::string shared(const std::string& relative);
  // Absolute path of a module's shipped parameters, config/modules/<module>.yaml (its --config).
  static std::string moduleConfig(const std::string& module);

 private:
  void remember(pid_t pid);
  void teardown();

  std::string dir_;
  std::string setFile_;
  std::string address_;
  int namingPort_ = 0;
  int watchdogPort_ = 0;
  std::map<std::string, int> ports_;
  pid_t watchdogPid_ = 0;
  std::map<pid_t, std::uint64_t> seen_;  // PID -> /proc start time
  std::unique_ptr<WatchdogClient> watchdog_;
};

// A TCP port on 127.0.0.1 that is free now and not handed out before by this process.
int freeLoopbackPort();

}  // namespace rgnav::testing
