// KernelPlanningMap: the PlanningMap of an RG Mapping Kernel running in the same process (the
// evaluations and tests map in process; the PathPlanning module reads the same views through the
// kernel's client library).
#pragma once

#include "core/nav/planning/PlanningMap.h"

namespace rgnav {

PlanningMap planningMapOf(const RgMappingKernel& kernel);

}  // namespace rgnav
