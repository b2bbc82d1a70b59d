// Fuzz target: an Intel raw-odometry JSON file (plain, gzip or xz) read to its end by
// IntelJsonLogReader.
#include "core/common/Errors.h"
#include "core/logs/IntelJsonLogReader.h"
#include "tests/fuzz/targets/FuzzInput.h"
#include "tests/fuzz/targets/FuzzTargets.h"

namespace rgnav::fuzz {

void fuzzIntelJsonReader(const std::uint8_t* data, std::size_t size) {
  try {
    IntelJsonLogReader reader(fuzzInputFile(data, size));
    while (reader.next()) {
    }
  } catch (const Error&) {
  }
}

}  // namespace rgnav::fuzz
