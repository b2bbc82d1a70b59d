// Fuzz target: a server set's YAML (config/sets/) parsed strictly by parseSetConfig, with the
// variables the watchdog defines.
#include "core/common/Errors.h"
#include "core/supervision/SetConfig.h"
#include "tests/fuzz/targets/FuzzInput.h"
#include "tests/fuzz/targets/FuzzTargets.h"

namespace rgnav::fuzz {

void fuzzSetConfig(const std::uint8_t* data, std::size_t size) {
  static const ConfigVars vars{{"RGNAV_ROOT", "/rgnav"}, {"RGNAV_BIN", "/rgnav/build/bin"},
                               {"RGNAV_SHARED", "/shared"}};
  try {
    parseSetConfig(fuzzText(data, size), "fuzz", vars, "/rgnav");
  } catch (const Error&) {
  }
}

}  // namespace rgnav::fuzz
