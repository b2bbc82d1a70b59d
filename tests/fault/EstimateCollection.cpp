// The localization fault test's client: estimates by scan ID, kills, restarts (see
// EstimateCollection.h).
#include "tests/fault/EstimateCollection.h"

#include <signal.h>

#include <chrono>
#include <stdexcept>

#include "clientlibs/localization/LocalizationClient.h"
#include "tests/fault/FaultSchedule.h"
#include "tests/fault/ScanEstimates.h"
#include "tests/support/cluster/Interruption.h"

namespace rgnav::testing {

namespace {

using Clock = std::chrono::steady_clock;

void pause() { sleepUntilOrInterrupted(Clock::now() + std::chrono::milliseconds(5)); }

// What `call` returns, asked again while the module is away (restarting).
template <class Call>
auto answered(const Call& call) {
  for (;;) {
    try {
      return call();
    } catch (const ModuleUnavailableError&) {
      pause();
    } catch (const ModuleFailedError&) {
      pause();
    }
  }
}

// A status counter of the module (0 if it has not set it).
std::uint64_t counter(LocalizationClient& localization, const std::string& name) {
  const ModuleStatusInfo status = answered([&] { return localization.status(); });
  const auto found = status.counters.find(name);
  return found == status.counters.end() ? 0 : found->second;
}

// Whether a restarted module resumed the particles of its checkpoint (rather than starting over
// at the first scan's odometry pose), once it holds particles either way; the checkpoint's scan
// if it did, 0 if not.
DataId resumedAt(LocalizationClient& localization, double limitSeconds) {
  const auto giveUp =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limitSeconds));
  while (!answered([&] { return localization.filterState().initialised; })) {
    if (Clock::now() > giveUp) throw std::runtime_error("the restarted module holds no particles");
    pause();
  }
  return counter(localization, "particles_resumed") > 0 ? counter(localization, "resumed_after_scan") : 0;
}

}  // namespace

CollectedRun collectEstimates(TestCluster& cluster, const AnchoredRun& run, int kills, double stallSeconds) {
  LocalizationClient localization(cluster.clientSettings());
  const DataId first = run.scans.front().id, last = run.scans.back().id;
  const auto target = [&](int k) { return first + (last - first) * DataId(k + 1) / DataId(kills + 1); };
  CollectedRun out;
  std::int64_t pid = cluster.describe("Localization").pid;
  const auto began = Clock::now();
  auto progress = began;
  DataId next = first;
  while (next <= last) {
    if (std::chrono::duration<double>(Clock::now() - progress).count() > stallSeconds)
      throw std::runtime_error("the module took no scan for " + std::to_string(stallSeconds) + " s (waiting for scan " +
                               std::to_string(next) + ")");
    try {
      const LocalizationStateView state = localization.filterState();
      if (state.lastScan < next) {
        pause();
        continue;
      }
      for (; next <= std::min(state.lastScan, last); ++next) {
        try {
          out.served.emplace(next, localization.estimateByScan(next).estimate.mapPose);
        } catch (const NotAvailableError&) {
          // taken by a process killed before the estimate was fetched, and resumed after it
        }
      }
      progress = Clock::now();
      if (out.kills == kills || state.lastScan < target(out.kills) ||
          counter(localization, "checkpoints_written") == 0)
        continue;
      ::kill(static_cast<pid_t>(pid), SIGKILL);
      ++out.kills;
      out.killedAfter.push_back(state.lastScan);
      pid = cluster
                .waitFor("Localization", [&](const ModuleProcessInfo& m) { return isRunning(m) && m.pid != pid; },
                         "restarted", std::chrono::seconds(60))
                .pid;
      out.resumedAfter.push_back(resumedAt(localization, stallSeconds));
      out.resumed += out.resumedAfter.back() > 0;
      progress = Clock::now();
    } catch (const ModuleUnavailableError&) {
      pause();
    } catch (const ModuleFailedError&) {
      pause();
    }
  }
  out.seconds = std::chrono::duration<double>(Clock::now() - began).count();
  ScanEstimates scored = estimatesOfEveryScan(run.scans, out.served);
  out.estimates = std::move(scored.estimates);
  out.propagated = scored.propagated;
  return out;
}

}  // namespace rgnav::testing
