// Names of task kinds, states and goals (Task.h), as logs and rgnav-nav print them.
#include "core/nav/tasks/Task.h"

#include <cstdio>

namespace rgnav {

std::string toString(TaskKind kind) {
  switch (kind) {
    case TaskKind::GoTo: return "goTo";
    case TaskKind::Explore: return "explore";
    case TaskKind::Stop: return "stop";
  }
  return "unknown";
}

std::string toString(TaskState state) {
  switch (state) {
    case TaskState::Queued: return "queued";
    case TaskState::Active: return "active";
    case TaskState::Reached: return "reached";
    case TaskState::Blocked: return "blocked";
    case TaskState::Cancelled: return "cancelled";
    case TaskState::Done: return "done";
  }
  return "unknown";
}

std::string describeGoal(const PlanGoal& goal) {
  switch (goal.kind) {
    case PlanGoal::Kind::Point: {
      char text[64];
      std::snprintf(text, sizeof text, "point %.2f %.2f", goal.point.x(), goal.point.y());
      return text;
    }
    case PlanGoal::Kind::Region: return "region " + std::to_string(goal.region.value());
    case PlanGoal::Kind::RegionName: return "region '" + goal.name + "'";
    case PlanGoal::Kind::Object: return "object '" + goal.name + "'";
  }
  return "unknown goal";
}

bool ended(TaskState state) { return state != TaskState::Queued && state != TaskState::Active; }

}  // namespace rgnav
