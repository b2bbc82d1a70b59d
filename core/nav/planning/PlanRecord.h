// PlanRecord: a plan as the PathPlanning module serves and keeps it (idl/PathPlanning.idl): the
// route planner's Plan (RoutePlanner.h) with its number, the request that made it and the start
// and goal it was asked for, so that followers can fetch it by ID and a repeated request gets it back.
#pragma once

#include <cstdint>

#include "core/nav/planning/RoutePlanner.h"

namespace rgnav {

using PlanId = std::uint64_t;  // 1, 2, 3, ... in the order the module made its plans

struct PlanRecord {
  PlanId id = 0;
  std::uint64_t request = 0;  // nonzero
  Pose2D start;
  PlanGoal goal;
  Plan plan;
};

}  // namespace rgnav
