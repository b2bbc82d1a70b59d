// LocalizationSet: the server set of the localization fault test (issue 28, `rgctl faulttest
// localization`) as a test cluster: the log playback serving the Laser (and Base) as fast as it
// is consumed, the RG Mapping Kernel holding the run's map from a checkpoint placed in its state
// directory (AnchoredRun.h), and the Localization module, started at the first scan's odometry
// pose (in the anchored frame: its corrected pose), checkpointing its particles every 0.2 s and
// restarted by the watchdog without limit.
// Pacing: the module is the playback's only consumer, and the playback releases a scan only when
// asked for it (`--speed max`; the module's look at the latest scan ID releases the next one): a
// lock-step in which the log waits for the module, also while the module restarts.
#pragma once

#include <memory>
#include <string>

#include "tests/fault/AnchoredRun.h"
#include "tests/support/cluster/TestCluster.h"

namespace rgnav::testing {

// Not started yet.
std::unique_ptr<TestCluster> localizationSet(const std::string& log, const AnchoredRun& run);

}  // namespace rgnav::testing
