// Conversions between HighLevelPlanning.idl types and the task types (see convert.h).
#include "clientlibs/highlevelplanning/convert.h"

#include "clientlibs/pathplanning/convert.h"
#include "core/common/Errors.h"

namespace rgnav {

RGNav::TaskKind toIdl(TaskKind kind) {
  switch (kind) {
    case TaskKind::GoTo: return RGNav::TASK_GOTO;
    case TaskKind::Explore: return RGNav::TASK_EXPLORE;
    case TaskKind::Stop: return RGNav::TASK_STOP;
  }
  throw InvalidArgumentError("unknown task kind");
}

TaskKind fromIdl(RGNav::TaskKind kind) {
  switch (kind) {
    case RGNav::TASK_GOTO: return TaskKind::GoTo;
    case RGNav::TASK_EXPLORE: return TaskKind::Explore;
    case RGNav::TASK_STOP: return TaskKind::Stop;
    default: break;
  }
  throw InvalidArgumentError("unknown task kind " + std::to_string(static_cast<int>(kind)));
}

RGNav::TaskState toIdl(TaskState state) {
  switch (state) {
    case TaskState::Queued: return RGNav::TASK_QUEUED;
    case TaskState::Active: return RGNav::TASK_ACTIVE;
    case TaskState::Reached: return RGNav::TASK_REACHED;
    case TaskState::Blocked: return RGNav::TASK_BLOCKED;
    case TaskState::Cancelled: return RGNav::TASK_CANCELLED;
    case TaskState::Done: return RGNav::TASK_DONE;
  }
  throw InvalidArgumentError("unknown task state");
}

TaskState fromIdl(RGNav::TaskState state) {
  switch (state) {
    case RGNav::TASK_QUEUED: return TaskState::Queued;
    case RGNav::TASK_ACTIVE: return TaskState::Active;
    case RGNav::TASK_REACHED: return TaskState::Reached;
    case RGNav::TASK_BLOCKED: return TaskState::Blocked;
    case RGNav::TASK_CANCELLED: return TaskState::Cancelled;
    case RGNav::TASK_DONE: return TaskState::Done;
    default: break;
  }
  throw InvalidArgumentError("unknown task state " + std::to_string(static_cast<int>(state)));
}

RGNav::TaskInfo toIdl(const Task& task) {
  RGNav::TaskInfo out;
  out.id = task.id;
  out.request = task.request;
  out.kind = toIdl(task.kind);
  out.goal = toIdl(task.goal);
  out.state = toIdl(task.state);
  out.reason = task.reason.c_str();
  out.progress = task.progress.c_str();
  out.drive = task.drive;
  out.drives = task.drives;
  out.distanceLeftM = task.distanceLeftM;
  return out;
}

Task fromIdl(const RGNav::TaskInfo& info) {
  Task task;
  task.id = info.id;
  task.request = info.request;
  task.kind = fromIdl(info.kind);
  task.goal = fromIdl(info.goal);
  task.state = fromIdl(info.state);
  task.reason = info.reason.in();
  task.progress = info.progress.in();
  task.drive = info.drive;
  task.drives = info.drives;
  task.distanceLeftM = info.distanceLeftM;
  return task;
}

RGNav::NamingQuestion toIdl(const NamingQuestion& question) {
  RGNav::NamingQuestion out;
  out.id = question.id;
  out.region = question.region.value();
  out.where.x = question.where.x();
  out.where.y = question.where.y();
  out.text = question.text.c_str();
  return out;
}

NamingQuestion fromIdl(const RGNav::NamingQuestion& question) {
  NamingQuestion out;
  out.id = question.id;
  out.region = RegionId(question.region);
  out.where = Eigen::Vector2d(question.where.x, question.where.y);
  out.text = question.text.in();
  return out;
}

}  // namespace rgnav
