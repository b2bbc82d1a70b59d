// The faults of a fault-injection run (see FaultSchedule.h).
#include "tests/fault/FaultSchedule.h"

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <random>

#include "core/logs/OpenLog.h"
#include "core/logs/ReplayMode.h"
#include "tests/support/cluster/Interruption.h"

namespace rgnav::testing {

using Clock = std::chrono::steady_clock;

bool isRunning(const ModuleProcessInfo& m) { return m.state == ProcessState::Running; }

FaultRecord injectFaults(TestCluster& cluster, const FaultPlan& plan) {
  std::vector<int> faults(static_cast<std::size_t>(plan.kills), SIGKILL);
  faults.insert(faults.end(), static_cast<std::size_t>(plan.stops), SIGSTOP);
  std::shuffle(faults.begin(), faults.end(), std::mt19937(plan.seed));
  const auto interval = std::chrono::duration<double>(plan.spanSeconds / double(faults.size() + 1));
  const auto begin = Clock::now();
  FaultRecord record;
  for (std::size_t i = 0; i < faults.size(); ++i) {
    sleepUntilOrInterrupted(begin + std::chrono::duration_cast<Clock::duration>(interval * double(i + 1)));
    if (plan.finished && plan.finished()) break;
    if (plan.killNaming && i == faults.size() / 2) {
      const auto naming = cluster.waitFor("NameService", isRunning, "running");
      ::kill(static_cast<pid_t>(naming.pid), SIGKILL);
      cluster.waitFor("NameService", [&](const ModuleProcessInfo& m) { return isRunning(m) && m.pid != naming.pid; },
                      "restarted");
      ++record.namingRestarts;
    }
    const std::string& target = plan.targets[i % plan.targets.size()];
    const auto victim = cluster.waitFor(target, isRunning, "running");
    const auto hit = Clock::now();
    ::kill(static_cast<pid_t>(victim.pid), faults[i]);
    (faults[i] == SIGKILL ? record.kills : record.stops)++;
    cluster.waitFor(target, [&](const ModuleProcessInfo& m) { return isRunning(m) && m.pid != victim.pid; },
                    "restarted");
    record.recoverySeconds.push_back(std::chrono::duration<double>(Clock::now() - hit).count());
    ++record.recovered;
  }
  return record;
}

double replayDuration(const std::string& log, const std::string& speed) {
  auto source = openLog(log);
  double first = -1, last = 0;
  while (auto record = source->next())
    if (const auto* scan = std::get_if<LaserScan>(&*record)) {
      if (first < 0) first = scan->stamp;
      last = scan->stamp;
    }
  return (last - first) / parseReplayMode(speed).speed;
}

}  // namespace rgnav::testing
