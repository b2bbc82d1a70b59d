// Names of task kinds and states (Task.h), as logs and rgnav-nav print them.
#include "core/nav/tasks/Task.h"

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

bool ended(TaskState state) { return state != TaskState::Queued && state != TaskState::Active; }

}  // namespace rgnav
