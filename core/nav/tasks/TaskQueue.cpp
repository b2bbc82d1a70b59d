// TaskQueue: numbering, first-in first-out activation, cancellation and outcomes (see TaskQueue.h).
#include "core/nav/tasks/TaskQueue.h"

#include <algorithm>
#include <cmath>

#include "core/common/Errors.h"

namespace rgnav {

namespace {

void checkGoal(const PlanGoal& goal) {
  switch (goal.kind) {
    case PlanGoal::Kind::Point:
      if (!goal.point.allFinite()) throw InvalidArgumentError("goal point is not finite");
      return;
    case PlanGoal::Kind::Region:
      if (goal.region.isNone()) throw InvalidArgumentError("goal region ID is 0");
      return;
    case PlanGoal::Kind::RegionName:
    case PlanGoal::Kind::Object:
      if (goal.name.empty()) throw InvalidArgumentError("goal name is empty");
      return;
  }
}

// The task with `state` first in `tasks` (a Task* or a const Task*, as `tasks` is); none if none.
template <class Tasks>
auto firstIn(Tasks& tasks, TaskState state) -> decltype(&tasks.front()) {
  auto it = std::find_if(tasks.begin(), tasks.end(), [&](const Task& t) { return t.state == state; });
  return it == tasks.end() ? nullptr : &*it;
}

}  // namespace

TaskQueue::TaskQueue(std::size_t keptEnded) : keptEnded_(keptEnded) {}

TaskQueue::TaskQueue(std::vector<Task> tasks, TaskId nextId, std::size_t keptEnded)
    : keptEnded_(keptEnded), nextId_(nextId) {
  TaskId last = 0;
  std::size_t active = 0;
  for (Task& task : tasks) {
    if (task.id <= last || task.id >= nextId)
      throw InvalidArgumentError("restored task " + std::to_string(task.id) + " is out of order");
    last = task.id;
    if (task.state == TaskState::Active && ++active > 1)
      throw InvalidArgumentError("restored queue has two active tasks");
    tasks_.push_back(std::move(task));
  }
}

Task& TaskQueue::add(Task task) {
  task.id = nextId_++;
  tasks_.push_back(std::move(task));
  Task& added = tasks_.back();
  forgetOldEnded();
  return added;
}

const Task& TaskQueue::goTo(const PlanGoal& goal, std::uint64_t request) {
  if (const Task* known = byRequest(request)) return *known;
  checkGoal(goal);
  Task task;
  task.request = request;
  task.kind = TaskKind::GoTo;
  task.goal = goal;
  return add(std::move(task));
}

const Task& TaskQueue::explore(std::uint64_t request) {
  if (const Task* known = byRequest(request)) return *known;
  Task task;
  task.request = request;
  task.kind = TaskKind::Explore;
  return add(std::move(task));
}

const Task& TaskQueue::stop(std::uint64_t request) {
  if (const Task* known = byRequest(request)) return *known;
  const std::string reason = "cancelled by stop task " + std::to_string(nextId_);
  for (Task& task : tasks_)
    if (!ended(task.state)) {
      task.state = TaskState::Cancelled;
      task.reason = reason;
    }
  Task task;
  task.request = request;
  task.kind = TaskKind::Stop;
  task.state = TaskState::Done;
  return add(std::move(task));
}

const Task& TaskQueue::cancel(TaskId id, const std::string& reason) {
  auto it = std::find_if(tasks_.begin(), tasks_.end(), [&](const Task& t) { return t.id == id; });
  if (it == tasks_.end()) throw NotAvailableError("no task " + std::to_string(id));
  if (!ended(it->state)) {
    it->state = TaskState::Cancelled;
    it->reason = reason;
  }
  return *it;
}

Task* TaskQueue::activeTask() { return firstIn(tasks_, TaskState::Active); }

const Task* TaskQueue::active() const { return firstIn(tasks_, TaskState::Active); }

const Task* TaskQueue::startNext() {
  if (Task* task = activeTask()) return task;
  Task* next = firstIn(tasks_, TaskState::Queued);
  if (next) next->state = TaskState::Active;
  return next;
}

void TaskQueue::setProgress(std::uint64_t drive, std::uint32_t drives, double distanceLeftM, const std::string& progress) {
  Task* task = activeTask();
  if (!task) return;
  task->drive = drive;
  task->drives = drives;
  task->distanceLeftM = distanceLeftM;
  task->progress = progress;
}

void TaskQueue::finish(TaskState outcome, const std::string& reason) {
  if (outcome != TaskState::Reached && outcome != TaskState::Blocked && outcome != TaskState::Done)
    throw InvalidArgumentError("a task ends reached, blocked or done, not " + toString(outcome));
  Task* task = activeTask();
  if (!task) throw InvalidArgumentError("no task is active");
  task->state = outcome;
  task->reason = reason;
  task->distanceLeftM = 0.0;
  forgetOldEnded();
}

const Task* TaskQueue::find(TaskId id) const {
  auto it = std::find_if(tasks_.begin(), tasks_.end(), [&](const Task& t) { return t.id == id; });
  return it == tasks_.end() ? nullptr : &*it;
}

const Task* TaskQueue::byRequest(std::uint64_t request) const {
  if (request == 0) return nullptr;
  auto it = std::find_if(tasks_.begin(), tasks_.end(), [&](const Task& t) { return t.request == request; });
  return it == tasks_.end() ? nullptr : &*it;
}

std::vector<Task> TaskQueue::tasks() const { return {tasks_.begin(), tasks_.end()}; }

void TaskQueue::forgetOldEnded() {
  std::size_t endedCount = static_cast<std::size_t>(
      std::count_if(tasks_.begin(), tasks_.end(), [](const Task& t) { return ended(t.state); }));
  for (auto it = tasks_.begin(); endedCount > keptEnded_ && it != tasks_.end();) {
    if (ended(it->state)) {
      it = tasks_.erase(it);
      --endedCount;
    } else {
      ++it;
    }
  }
}

}  // namespace rgnav
