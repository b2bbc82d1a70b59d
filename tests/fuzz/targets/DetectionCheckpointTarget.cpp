// Fuzz target: the GatewayDetection module's checkpoint text decoded by deserializeDetection.
#include "core/common/Errors.h"
#include "core/gateways/detection/DetectionStateCodec.h"
#include "tests/fuzz/targets/FuzzInput.h"
#include "tests/fuzz/targets/FuzzTargets.h"

namespace rgnav::fuzz {

void fuzzDetectionCheckpoint(const std::uint8_t* data, std::size_t size) {
  try {
    deserializeDetection(fuzzText(data, size));
  } catch (const Error&) {
  }
}

}  // namespace rgnav::fuzz
