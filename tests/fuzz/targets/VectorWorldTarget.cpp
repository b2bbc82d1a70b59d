// Fuzz target: a vector world's YAML (config/worlds/) loaded strictly by loadVectorWorld. A
// floor-plan image it names is not there: a FileError.
#include "core/common/Errors.h"
#include "core/sim/world/VectorWorldYaml.h"
#include "tests/fuzz/targets/FuzzInput.h"
#include "tests/fuzz/targets/FuzzTargets.h"

namespace rgnav::fuzz {

void fuzzVectorWorld(const std::uint8_t* data, std::size_t size) {
  try {
    loadVectorWorld(fuzzInputFile(data, size));
  } catch (const Error&) {
  }
}

}  // namespace rgnav::fuzz
