// Helpers shared by the integration tests: the playback module's command line, predicates on
// the watchdog's view of a module, the watchdog's event log, reading a whole scan stream,
// whether a process is gone, a scratch directory, and the field a refused call names. Every wait is bounded (Wait.h: waitUntil).
#pragma once

#include <sys/types.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "clientlibs/laser/LaserClient.h"
#include "tests/support/cluster/TestCluster.h"
#include "watchdog/ProcStat.h"
#include "watchdog/testing/Wait.h"

namespace rgnav::testing {

inline std::string intelLog() { return TestCluster::shared("data/laser/corrected/intel-corrected.log.gz"); }
inline constexpr std::size_t kIntelScans = 910;
inline constexpr std::size_t kIntelOdometry = 14541;

// Set-level YAML: quick restarts, so that crash loops reach FATAL in well under a second.
inline const std::string kFastBackoff = "defaults: {backoff_initial_s: 0.05, backoff_max_s: 0.4}";

// The playback server on `log`, as fast as consumed, with extra options appended.
inline std::vector<std::string> playbackCommand(const std::string& log, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> command{TestCluster::program("rgnav-carmen-playback"), "--log", log, "--speed", "max"};
  command.insert(command.end(), extra.begin(), extra.end());
  return command;
}

inline bool isRunning(const ModuleProcessInfo& m) { return m.state == ProcessState::Running; }
inline auto inState(ProcessState state) {
  return [state](const ModuleProcessInfo& m) { return m.state == state; };
}
// Running again under a PID other than `oldPid`: a restart happened.
inline auto runningAgainAfter(std::int64_t oldPid) {
  return [oldPid](const ModuleProcessInfo& m) { return isRunning(m) && m.pid != 0 && m.pid != oldPid; };
}

// Events of `module` named `what`, oldest first.
inline std::vector<SupervisionEvent> eventsOf(WatchdogClient& watchdog, const std::string& module,
                                              const std::string& what) {
  std::vector<SupervisionEvent> out;
  for (const SupervisionEvent& e : watchdog.eventsSince(0, 1000))
    if (e.module == module && e.what == what) out.push_back(e);
  return out;
}

// Polls until the event exists; fails the test after `limit`.
inline SupervisionEvent waitForEvent(WatchdogClient& watchdog, const std::string& module, const std::string& what,
                                     std::chrono::milliseconds limit = std::chrono::seconds(20)) {
  std::vector<SupervisionEvent> found;
  waitUntil(
      [&] {
        found = eventsOf(watchdog, module, what);
        return !found.empty();
      },
      "a '" + what + "' event of " + module, limit, std::chrono::milliseconds(20));
  return found.front();
}

// Reads every scan after `after` until the server reports the end of data; bounded in calls.
inline std::vector<LaserScan> readAllScans(LaserClient& laser, std::uint32_t batch = 100, DataId after = 0) {
  std::vector<LaserScan> scans;
  for (int call = 0; call < 100000; ++call) {
    DataBatch<LaserScan> got = laser.scansSince(after, batch);
    for (LaserScan& scan : got.records) {
      after = scan.id;
      scans.push_back(std::move(scan));
    }
    if (got.records.empty() && got.endOfData && after >= got.latestId) return scans;
  }
  throw std::runtime_error("the scan stream did not end");
}

// A directory of its own under the system's temporary directory ("<prefix>-<pid>"), removed with
// everything in it when the object goes, also when a test fails.
struct ScratchDir {
  explicit ScratchDir(const std::string& prefix)
      : path(std::filesystem::temp_directory_path() / (prefix + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  std::string file(const std::string& name) const { return (path / name).string(); }
  std::filesystem::path path;
};

// The process start time, to tell a PID from a later process that reuses it.
inline std::uint64_t startTimeOf(std::int64_t pid) {
  const auto stat = readProcStat(static_cast<pid_t>(pid));
  if (!stat) throw std::runtime_error("no process " + std::to_string(pid));
  return stat->startTime;
}

// Gone: /proc/<pid> absent, a zombie, or the PID now names another process.
inline bool processGone(std::int64_t pid, std::uint64_t startTime) {
  return !isProcessAlive(static_cast<pid_t>(pid), startTime);
}

// The field a call's BadArgumentError names; "(accepted)" if it succeeded.
template <class F>
std::string refusedField(F&& call) {
  try {
    call();
  } catch (const BadArgumentError& e) {
    return e.field();
  }
  return "(accepted)";
}

}  // namespace rgnav::testing
