// Validation of the High-Level Planning module's parameters (see HighLevelPlanningConfig.h).
#include "core/nav/tasks/HighLevelPlanningConfig.h"

#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

void validate(const HighLevelPlanningConfig& config) {
  if (!(std::isfinite(config.pollPeriodS) && config.pollPeriodS >= 0.01 && config.pollPeriodS <= 10.0))
    throw ConfigError("poll_period_s must lie in [0.01, 10] s");
  validate(config.exploration);
  validate(config.routePlanner);
}

}  // namespace rgnav
