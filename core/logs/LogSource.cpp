// LogSource: checks of the shared reader options.
#include "core/logs/LogSource.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

void validate(const LogReaderOptions& options) {
  if (!std::isfinite(options.maxRange) || options.maxRange <= 0.0) {
    throw InvalidArgumentError("log reader: maxRange must be a positive number of metres, got " +
                               std::to_string(options.maxRange));
  }
  if (options.maxLineLength == 0) {
    throw InvalidArgumentError("log reader: maxLineLength must be positive");
  }
}

}  // namespace rgnav
