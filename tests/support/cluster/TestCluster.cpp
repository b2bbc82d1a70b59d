// The integration-test server set (see TestCluster.h).
#include "tests/support/cluster/TestCluster.h"

#include <netinet/in.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <stdexcept>

#include "core/config/ShippedConfig.h"
#include "tests/support/WaitUntil.h"
#include "tests/support/cluster/Interruption.h"
#include "watchdog/ProcStat.h"
#include "watchdog/Spawn.h"

namespace fs = std::filesystem;

namespace rgnav::testing {

int freeLoopbackPort() {
  static std::mutex mutex;
  static std::set<int> handedOut;
  std::lock_guard lock(mutex);
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = 0;
    socklen_t len = sizeof addr;
    const bool ok = fd >= 0 && ::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0 &&
                    ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) == 0;
    if (fd >= 0) ::close(fd);
    const int port = ntohs(addr.sin_port);
    if (ok && handedOut.insert(port).second) return port;
  }
  throw std::runtime_error("no free loopback port found");
}

std::string TestCluster::program(const std::string& name) {
  const char* bin = std::getenv("RGNAV_BIN");
  return (bin && *bin ? fs::path(bin) : fs::canonical("/proc/self/exe").parent_path()) / name;
}

std::string TestCluster::moduleConfig(const std::string& module) {
  return shippedConfigFile("modules/" + module + ".yaml");
}

std::string TestCluster::shared(const std::string& relative) {
  const char* shared = std::getenv("RGNAV_SHARED");
  return (fs::path(shared && *shared ? shared : "../shared") / relative).string();
}

namespace {
std::string yamlList(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", \"" : "\"") + items[i] + "\"";
  return out + "]";
}
}  // namespace

TestCluster::TestCluster(std::vector<ClusterModule> modules, std::string setYaml, ClusterHost host)
    : address_(host.address) {
  std::string pattern = (fs::temp_directory_path() / "rgnav-cluster-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed for " + pattern);
  dir_ = pattern;
  const bool managed = host.externalNamingPort == 0;
  namingPort_ = managed ? freeLoopbackPort() : host.externalNamingPort;
  watchdogPort_ = freeLoopbackPort();
  std::string yaml = "robot: tumbot\nhost: " + address_ + "\nrun_dir: " + dir_ + "/run\nnaming: {host: 127.0.0.1, port: " +
                     std::to_string(namingPort_) + ", managed: " + (managed ? "true" : "false") +
                     "}\nwatchdog: {port: " + std::to_string(watchdogPort_) + "}\n" + setYaml + "\nmodules:\n";
  for (const ClusterModule& m : modules) {
    ports_[m.name] = freeLoopbackPort();
    yaml += "  - name: " + m.name + "\n    command: " + yamlList(m.command) + "\n    port: " +
            std::to_string(ports_[m.name]) + "\n    objects: " + yamlList(m.objects) + "\n";
    if (!m.after.empty()) yaml += "    after: " + yamlList(m.after) + "\n";
    if (!m.policyYaml.empty()) yaml += "    " + m.policyYaml + "\n";
  }
  setFile_ = dir_ + "/" + host.name + ".yaml";
  std::ofstream(setFile_) << yaml;
}

TestCluster::~TestCluster() { teardown(); }

void TestCluster::remember(pid_t pid) {
  if (pid <= 1 || seen_.count(pid)) return;
  if (const auto stat = readProcStat(pid)) seen_[pid] = stat->startTime;
}

void TestCluster::start(const std::vector<std::string>& running) {
  SpawnSpec spec;
  spec.argv = {program("rgnav-watchdog"), "--set", setFile_, "--root", dir_};
  spec.logFile = dir_ + "/watchdog.log";
  spec.parentDeathSignal = SIGTERM;
  watchdogPid_ = spawnProcess(spec);
  remember(watchdogPid_);
  std::vector<std::string> names = running;
  if (names.empty())
    for (const auto& [name, port] : ports_) names.push_back(name);
  for (const std::string& name : names)
    waitFor(name, [](const ModuleProcessInfo& m) { return m.state == ProcessState::Running; }, "running");
  for (const ModuleProcessInfo& m : watchdog().modules()) remember(static_cast<pid_t>(m.pid));  // omniNames too
}

void TestCluster::stopWatchdog(int signal) {
  if (watchdogPid_ <= 0) return;
  ::kill(watchdogPid_, signal);
  ::waitpid(watchdogPid_, nullptr, 0);
  watchdogPid_ = 0;
  watchdog_.reset();
}

WatchdogClient& TestCluster::watchdog() {
  if (!watchdog_) watchdog_ = std::make_unique<WatchdogClient>(HostPort{address_, watchdogPort_}, clientSettings());
  return *watchdog_;
}

ClientSettings TestCluster::clientSettings() const {
  ClientSettings settings;
  settings.namingHost = "127.0.0.1";
  settings.namingPort = namingPort_;
  settings.retryBudget = std::chrono::seconds(20);
  return settings;
}

ModuleProcessInfo TestCluster::describe(const std::string& name) {
  ModuleProcessInfo info = watchdog().describeModule(name);
  remember(static_cast<pid_t>(info.pid));
  return info;
}

ModuleProcessInfo TestCluster::waitFor(const std::string& name,
                                       const std::function<bool(const ModuleProcessInfo&)>& pred,
                                       const std::string& what, std::chrono::milliseconds limit) {
  ModuleProcessInfo info;
  const bool reached = pollUntil(
      [&] {
        throwIfInterrupted();
        info = describe(name);
        return pred(info);
      },
      limit);
  if (!reached)
    throw std::runtime_error("timed out waiting for " + name + " to be " + what + " (state " + toString(info.state) +
                             ", last event: " + info.lastEvent + ")");
  return info;
}

void TestCluster::teardown() {
  if (watchdogPid_ > 0) {
    try {
      for (const auto& m : watchdog().modules()) remember(static_cast<pid_t>(m.pid));
    } catch (const std::exception&) {
      // The watchdog no longer answers; the PIDs seen so far are all we can clean up.
    }
    ::kill(watchdogPid_, SIGTERM);
    const bool ended = pollUntil([&] { return ::waitpid(watchdogPid_, nullptr, WNOHANG) != 0; },
                                 std::chrono::seconds(20), std::chrono::milliseconds(10));
    if (!ended) {
      ::kill(watchdogPid_, SIGKILL);
      ::waitpid(watchdogPid_, nullptr, 0);
    }
  }
  for (const auto& [pid, startTime] : seen_) {
    const auto stat = readProcStat(pid);
    if (stat && stat->startTime == startTime) {
      ::kill(-pid, SIGKILL);
      ::kill(pid, SIGKILL);
    }
  }
  if (!std::getenv("RGNAV_KEEP_TEST_DIRS")) {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
}

}  // namespace rgnav::testing
