// Conversions between HighLevelPlanning.idl types and the task types of core/nav/tasks (Task.h,
// NamingQuestion.h): task kinds and states, tasks, naming questions. Goals convert as the
// PathPlanning module's (clientlibs/pathplanning/convert.h).
#pragma once

#include "HighLevelPlanning.hh"
#include "core/nav/tasks/NamingQuestion.h"
#include "core/nav/tasks/Task.h"

namespace rgnav {

RGNav::TaskKind toIdl(TaskKind kind);
TaskKind fromIdl(RGNav::TaskKind kind);     // InvalidArgumentError for an unknown kind
RGNav::TaskState toIdl(TaskState state);
TaskState fromIdl(RGNav::TaskState state);  // InvalidArgumentError for an unknown state
RGNav::TaskInfo toIdl(const Task& task);
Task fromIdl(const RGNav::TaskInfo& info);
RGNav::NamingQuestion toIdl(const NamingQuestion& question);
NamingQuestion fromIdl(const RGNav::NamingQuestion& question);

}  // namespace rgnav
