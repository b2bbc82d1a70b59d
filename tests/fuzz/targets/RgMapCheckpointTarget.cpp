// Fuzz target: the RG Mapping Kernel's checkpoint decoded by deserializeRgMap. The input holds
// both texts: the map, a NUL byte, the scan journal (no NUL: all map, empty journal).
#include "core/common/Errors.h"
#include "core/rgmap/kernel/RgMapCodec.h"
#include "tests/fuzz/targets/FuzzInput.h"
#include "tests/fuzz/targets/FuzzTargets.h"

namespace rgnav::fuzz {

void fuzzRgMapCheckpoint(const std::uint8_t* data, std::size_t size) {
  const std::string input = fuzzText(data, size);
  const std::size_t split = input.find('\0');
  try {
    if (split == std::string::npos) {
      deserializeRgMap(input, "");
    } else {
      deserializeRgMap(input.substr(0, split), input.substr(split + 1));
    }
  } catch (const Error&) {
  }
}

}  // namespace rgnav::fuzz
