// MappingSet: the mapping chain as a test cluster (a log playback or the demo's simulator ->
// ScanMapper -> GatewayDetection -> RG Mapping Kernel, each restarted without limit), and the
// finished map it exports, for the fault programs that compare a disturbed run's map with an
// undisturbed one.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/cluster/TestCluster.h"

namespace rgnav::testing {

// log: the CARMEN log to replay; models: trained gateway HMMs; speed: "x<k>" or "realtime".
std::vector<ClusterModule> mappingSet(const std::string& log, const std::string& models, const std::string& speed);

// The modules of config/sets/demo-mapping.yaml (the simulator's lock-step tour of the office
// floor and the mapping chain), each restarted without limit; the kernel exports into the cluster's run
// directory instead of the project's out/.
std::vector<ClusterModule> demoSet();
// The modules of a shipped set (`relative` below config/, e.g. "sets/demo.yaml") in the same way.
std::vector<ClusterModule> shippedSetModules(const std::string& relative);

// Waits until the kernel has taken in the whole log; throws std::runtime_error after limitSeconds.
void waitForEndOfMap(TestCluster& cluster, double limitSeconds);

// Waits until the kernel has mapped the whole log, exports the map into the kernel's export root
// (<run dir>/exports) as `name` and returns the parsed JSON. Throws std::runtime_error after
// limitSeconds.
nlohmann::json finishedMap(TestCluster& cluster, double limitSeconds, const std::string& name = "map");

// Exports the kernel's map as it is now (as finishedMap, without waiting for the end of the data).
nlohmann::json exportedMap(TestCluster& cluster, const std::string& name);

}  // namespace rgnav::testing
