// PlanningErrors: the typed failures of the grid planners (in the manner of Navigation2's
// StartOccupied / GoalOccupied / NoValidPathCouldBeFound), so callers can tell them apart.
#pragma once

#include "core/common/Errors.h"

namespace rgnav {

// The start lies outside the grid or too close to an obstacle for the robot.
class StartBlockedError : public Error {
 public:
  using Error::Error;
};

// The goal lies outside the grid or too close to an obstacle for the robot.
class GoalBlockedError : public Error {
 public:
  using Error::Error;
};

// Start and goal are free, but not connected through space the robot fits through.
class NoPathError : public Error {
 public:
  using Error::Error;
};

}  // namespace rgnav
