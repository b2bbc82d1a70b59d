// DemoRun: the navigating demo's orchestration program (rgnav-demo, tools/demo) run as a child
// process on a test cluster of config/sets/demo.yaml (NavigationSet.h), with its output echoed
// line by line, its summary line parsed, and the facts of the map it leaves in the kernel that a
// disturbed run is compared on with an undisturbed one (rgnav-faulttest-navigation).
#pragma once

#include <chrono>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/cluster/TestCluster.h"

namespace rgnav::testing {

// The files rgnav-demo is given (--world, --answers, --tasks).
struct DemoFiles {
  std::string world, answers, tasks;
};

struct DemoOutcome {
  int exitCode = -1;  // rgnav-demo's (0: explored, every task reached, no collision)
  // The last line "demo: explored_share=… regions=… …" as key -> value; empty if it printed none.
  std::map<std::string, std::string> summary;

  // summary[key], or `fallback` if the line lacks it.
  std::string field(const std::string& key, const std::string& fallback = "?") const;
};

// Runs rgnav-demo on the cluster until it ends; its lines go to stdout prefixed with `prefix`.
// Its own files (the driven path) go into <cluster dir>/<name>. Throws std::runtime_error if it
// runs longer than `limit` (it is killed), InterruptedError on a termination signal.
DemoOutcome runDemo(TestCluster& cluster, const DemoFiles& files, const std::string& name, const std::string& prefix,
                    std::chrono::seconds limit);

// What a map is compared on: counts of regions, gateways and neutralised gateways, the gateways'
// classes and the regions' names (both sorted), the RG graph's sizes and the regions' total area.
struct MapFacts {
  std::size_t regions = 0, gateways = 0, neutralised = 0, graphNodes = 0, graphEdges = 0;
  std::vector<std::string> gatewayClasses, regionNames;
  double areaM2 = 0.0;
};

MapFacts mapFacts(const nlohmann::json& exportedMap);  // an exported map (RGMAP_JSON.md)
nlohmann::json toJson(const MapFacts& facts);
MapFacts mapFactsFromJson(const nlohmann::json& saved);  // what toJson wrote

}  // namespace rgnav::testing
