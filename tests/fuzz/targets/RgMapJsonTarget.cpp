// Fuzz target: an exported RG map (core/rgmap/export/RGMAP_JSON.md) read by planningMapFromJson,
// as rgnav-plan --map reads a file a user hands it.
#include "core/common/Errors.h"
#include "core/nav/planning/PlanningMapJson.h"
#include "tests/fuzz/targets/FuzzInput.h"
#include "tests/fuzz/targets/FuzzTargets.h"

namespace rgnav::fuzz {

void fuzzRgMapJson(const std::uint8_t* data, std::size_t size) {
  try {
    planningMapFromJson(fuzzText(data, size), "fuzz.rgmap.json");
  } catch (const Error&) {
  }
}

}  // namespace rgnav::fuzz
