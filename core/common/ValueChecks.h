// ValueChecks: range checks for configuration values and call arguments. A configuration value
// out of range is a ConfigError, a bad call argument an InvalidArgumentError; both name the value.
#pragma once

#include <cmath>
#include <string>

#include "core/common/Errors.h"

namespace rgnav {

inline void requirePositive(double value, const std::string& what) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw ConfigError(what + " must be a positive finite number");
  }
}

inline void requireNonNegative(double value, const std::string& what) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw ConfigError(what + " must be a non-negative finite number");
  }
}

inline void requireFiniteArgument(double value, const std::string& what) {
  if (!std::isfinite(value)) {
    throw InvalidArgumentError(what + " must be finite");
  }
}

}  // namespace rgnav
