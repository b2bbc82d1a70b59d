// Fuzz target: the ScanMapper's checkpoint bytes decoded (and checked) by deserializeState.
#include <string_view>

#include "core/common/Errors.h"
#include "core/slam/SlamStateCodec.h"
#include "tests/fuzz/targets/FuzzTargets.h"

namespace rgnav::fuzz {

void fuzzSlamCheckpoint(const std::uint8_t* data, std::size_t size) {
  try {
    deserializeState(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const Error&) {
  }
}

}  // namespace rgnav::fuzz
