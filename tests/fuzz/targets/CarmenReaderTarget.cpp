// Fuzz target: a CARMEN log (plain, gzip or xz) read to its end by CarmenLogReader.
#include "core/common/Errors.h"
#include "core/logs/CarmenLogReader.h"
#include "tests/fuzz/targets/FuzzInput.h"
#include "tests/fuzz/targets/FuzzTargets.h"

namespace rgnav::fuzz {

void fuzzCarmenReader(const std::uint8_t* data, std::size_t size) {
  try {
    CarmenLogReader reader(fuzzInputFile(data, size));
    while (reader.next()) {
    }
  } catch (const Error&) {
  }
}

}  // namespace rgnav::fuzz
