// Fuzz target: the simulator's YAML (config/sim/) parsed strictly by parseSimulationConfig.
#include "core/common/Errors.h"
#include "core/sim/SimulationConfigYaml.h"
#include "tests/fuzz/targets/FuzzInput.h"
#include "tests/fuzz/targets/FuzzTargets.h"

namespace rgnav::fuzz {

void fuzzSimulationConfig(const std::uint8_t* data, std::size_t size) {
  try {
    parseSimulationConfig(fuzzText(data, size));
  } catch (const Error&) {
  }
}

}  // namespace rgnav::fuzz
