// FaultSchedule: how long a log's replay takes, and the faults of a fault-injection run: `kills` SIGKILLs and `stops` SIGSTOPs in a
// seeded order, spread evenly over `spanSeconds`, each dealt to the next of `targets` in turn
// (round robin) while it runs; omniNames is SIGKILLed once half way (unless killNaming is false).
// The faults stop early once `finished` (if given) holds: the run they disturb is over. After every fault it waits
// until the watchdog has the module running again under a new PID and records how long that took.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tests/support/cluster/TestCluster.h"

namespace rgnav::testing {

struct FaultPlan {
  std::vector<std::string> targets;
  int kills = 0;
  int stops = 0;
  double spanSeconds = 0.0;
  unsigned seed = 7;
  bool killNaming = true;
  std::function<bool()> finished = {};
};

struct FaultRecord {
  int kills = 0, stops = 0, recovered = 0, namingRestarts = 0;
  std::vector<double> recoverySeconds;
};

FaultRecord injectFaults(TestCluster& cluster, const FaultPlan& plan);

// Seconds from the log's first to its last scan, divided by the replay speed ("x60", "realtime").
double replayDuration(const std::string& log, const std::string& speed);

bool isRunning(const ModuleProcessInfo& m);

}  // namespace rgnav::testing
