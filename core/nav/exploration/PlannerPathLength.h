// PlannerPathLength: the PathLength an exploration strategy asks (ExplorationStrategy.h) from a
// route planner in the same process (the High-Level Planning module, the exploration evaluation,
// the tests): the length of the planned path from the robot to the point, none where the planner
// finds no path (NoPathError, or a region planner's StartBlockedError / GoalBlockedError).
#pragma once

#include "core/nav/exploration/ExplorationStrategy.h"
#include "core/nav/planning/RoutePlanner.h"

namespace rgnav {

// `planner` must outlive the functor; it plans on the planner's map at the time of each call.
PathLength plannerPathLength(const RoutePlanner& planner, const Pose2D& robot);

}  // namespace rgnav
