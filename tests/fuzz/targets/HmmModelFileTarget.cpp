// Fuzz target: a gateway HMM model file (config/gateways/) loaded by loadHmmModels.
#include "core/common/Errors.h"
#include "core/gateways/classify/HmmModelFile.h"
#include "tests/fuzz/targets/FuzzInput.h"
#include "tests/fuzz/targets/FuzzTargets.h"

namespace rgnav::fuzz {

void fuzzHmmModelFile(const std::uint8_t* data, std::size_t size) {
  try {
    loadHmmModels(fuzzInputFile(data, size));
  } catch (const Error&) {
  }
}

}  // namespace rgnav::fuzz
