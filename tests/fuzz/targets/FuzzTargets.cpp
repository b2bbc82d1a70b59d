// The table of fuzz targets by name.
#include "tests/fuzz/targets/FuzzTargets.h"

#include <algorithm>
#include <string>

#include "core/common/Errors.h"

namespace rgnav::fuzz {

const std::vector<NamedFuzzTarget>& fuzzTargets() {
  static const std::vector<NamedFuzzTarget> targets = {
      {"carmen_reader", fuzzCarmenReader},
      {"intel_json_reader", fuzzIntelJsonReader},
      {"set_config", fuzzSetConfig},
      {"vector_world", fuzzVectorWorld},
      {"simulation_config", fuzzSimulationConfig},
      {"module_config", fuzzModuleConfig},
      {"slam_checkpoint", fuzzSlamCheckpoint},
      {"detection_checkpoint", fuzzDetectionCheckpoint},
      {"rgmap_checkpoint", fuzzRgMapCheckpoint},
      {"rgmap_json", fuzzRgMapJson},
      {"hmm_model_file", fuzzHmmModelFile},
  };
  return targets;
}

FuzzTarget fuzzTarget(std::string_view name) {
  const auto& targets = fuzzTargets();
  const auto it = std::find_if(targets.begin(), targets.end(),
                               [&](const NamedFuzzTarget& target) { return target.name == name; });
  if (it == targets.end()) {
    throw InvalidArgumentError("no fuzz target named '" + std::string(name) + "'");
  }
  return it->run;
}

}  // namespace rgnav::fuzz
