// Task: one task of the High-Level Planning module (thesis chapter 1: "go to the closet"; chapter 7:
// exploration; idl/HighLevelPlanning.idl): what it asks for, the state it is in, and what its
// drives have done. Plain values for the task queue (TaskQueue.h), the module, its client library
// and its checkpoint.
#pragma once

#include <cstdint>
#include <string>

#include "core/nav/planning/RoutePlanner.h"

namespace rgnav {

using TaskId = std::uint64_t;  // 1, 2, 3, ... in the order the queue took the tasks

enum class TaskKind { GoTo, Explore, Stop };
enum class TaskState { Queued, Active, Reached, Blocked, Cancelled, Done };

std::string toString(TaskKind kind);
std::string toString(TaskState state);
// "point 1.50 -2.00", "region 3", "region 'kitchen'", "object 'closet'": for progress and logs.
std::string describeGoal(const PlanGoal& goal);
// Whether a task in `state` has ended (reached, blocked, cancelled, done).
bool ended(TaskState state);

struct Task {
  TaskId id = 0;
  std::uint64_t request = 0;   // the request that made it (0: none)
  TaskKind kind = TaskKind::GoTo;
  PlanGoal goal;               // GoTo: where to
  TaskState state = TaskState::Queued;
  std::string reason;          // Blocked: why; Cancelled: by what
  std::string progress;        // one line: what it does now
  std::uint64_t drive = 0;     // the CollisionAvoidance drive's request ID it runs now (0: none)
  std::uint32_t drives = 0;    // drives started for it
  double distanceLeftM = 0.0;  // of the drive running now
};

}  // namespace rgnav
