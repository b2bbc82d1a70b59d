// EstimateCollection: the localization fault test's client (issue 28, `rgctl faulttest
// localization`): follows the Localization module of a LocalizationSet as it localizes scans
// 1..lastScan and fetches the estimate of every scan by ID as soon as the module took it
// (filterState().lastScan), keeping the first one served for each scan (what a client saw live).
// With `kills` > 0 it SIGKILLs the module that often, spread evenly over the scan IDs: the k-th
// kill once the module took scan k * lastScan / (kills + 1) and has written a checkpoint of its
// own since it started (so that every restart has a checkpoint to resume from, not only the
// first). After each kill it waits for the watchdog's restart and, once the new process holds
// particles, asks it whether it resumed them from the checkpoint (its status counters
// particles_resumed and resumed_after_scan) - a process that loaded the checkpoint but started
// over at the first scan's odometry pose would localize as well here, so only this tells.
// A scan the module never served an estimate for is scored as ScanEstimates.h says (`propagated`).
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "tests/fault/AnchoredRun.h"
#include "tests/support/cluster/TestCluster.h"

namespace rgnav::testing {

struct CollectedRun {
  std::map<DataId, Pose2D> served;  // the first estimate (map pose) the module served per scan
  std::vector<Pose2D> estimates;    // per scan of the run: served, or propagated
  std::size_t propagated = 0;
  int kills = 0;
  int resumed = 0;                  // restarts that resumed the checkpoint's particles
  std::vector<DataId> killedAfter;  // the module's last scan when it was killed
  std::vector<DataId> resumedAfter; // the checkpoint's scan the restarted module resumed at (0: none)
  double seconds = 0.0;             // wall time from the first scan to the last estimate
};

// The cluster runs. Throws std::runtime_error when the module makes no progress for
// `stallSeconds` or does not serve the first scan's estimate (its start at scan 1 failed).
CollectedRun collectEstimates(TestCluster& cluster, const AnchoredRun& run, int kills, double stallSeconds);

}  // namespace rgnav::testing
