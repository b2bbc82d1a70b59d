// Test helper: what differs between two plan records (PlanRecord.h), field by field with exact
// equality of every number; empty if they are the same plan.
#pragma once

#include <string>

#include "core/nav/planning/PlanRecord.h"

namespace rgnav::testing {

std::string planDifference(const PlanRecord& a, const PlanRecord& b);

}  // namespace rgnav::testing
