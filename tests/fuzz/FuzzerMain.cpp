// The libFuzzer entry of one fuzz target: each fuzzer executable of build-fuzz/ is this file
// compiled with RGNAV_FUZZ_TARGET set to the target's name (tests/fuzz/CMakeLists.txt).
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/targets/FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const rgnav::fuzz::FuzzTarget target = rgnav::fuzz::fuzzTarget(RGNAV_FUZZ_TARGET);
  target(data, size);
  return 0;
}
