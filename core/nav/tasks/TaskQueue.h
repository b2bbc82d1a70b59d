// TaskQueue: the tasks of the High-Level Planning module (idl/HighLevelPlanning.idl; thesis chapter
// 1: tasks such as "go to the closet"), numbered 1, 2, 3, ... as they come, carried out one at a
// time in the order they came (first in, first out). A task is Queued, then Active, then ends
// Reached (goTo), Done (explore, stop), Blocked (with why) or Cancelled. stop cancels every task
// (the caller stops the robot) and is itself Done at once. The queue keeps every task that has not
// ended and the latest `keptEnded` ended ones, so followers can read outcomes by ID. A request ID
// the queue holds a task of is answered with that task and changes nothing (a client's retry).
// No middleware and no clock: the module (servers/highlevelplanning) drives the active task and
// reports its outcome.
#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

#include "core/nav/tasks/Task.h"

namespace rgnav {

class TaskQueue {
 public:
  static constexpr std::size_t kKeptEnded = 100;

  TaskQueue() = default;
  explicit TaskQueue(std::size_t keptEnded);
  // A queue restored from a checkpoint: its tasks (by ID) and the ID the next task gets. Throws
  // InvalidArgumentError for tasks out of order, an ID at or beyond nextId, or two active tasks.
  TaskQueue(std::vector<Task> tasks, TaskId nextId, std::size_t keptEnded = kKeptEnded);

  // Queue a task (see above for a repeated request). InvalidArgumentError for a non-finite point
  // or an empty name.
  const Task& goTo(const PlanGoal& goal, std::uint64_t request);
  const Task& explore(std::uint64_t request);
  // Cancels every queued task and the active one ("cancelled by stop task N") and adds the stop
  // task, Done.
  const Task& stop(std::uint64_t request);
  // Cancels task `id` (queued or active) with `reason`; a task that has ended is answered as it
  // is. NotAvailableError for a task the queue does not keep.
  const Task& cancel(TaskId id, const std::string& reason);

  // The active task; none while nothing is active.
  const Task* active() const;
  // If no task is active, the oldest queued one becomes Active; answers the active task (none if
  // nothing is queued).
  const Task* startNext();
  // The active task's drive and progress (ignored while none is active).
  void setProgress(std::uint64_t drive, std::uint32_t drives, double distanceLeftM, const std::string& progress);
  // Ends the active task with `outcome` (Reached, Blocked or Done) and `reason`.
  // InvalidArgumentError for another state or when no task is active.
  void finish(TaskState outcome, const std::string& reason = {});

  const Task* find(TaskId id) const;
  const Task* byRequest(std::uint64_t request) const;  // none for request 0
  std::vector<Task> tasks() const;                     // by ID
  TaskId nextId() const { return nextId_; }

 private:
  Task& add(Task task);
  Task* activeTask();
  void forgetOldEnded();

  std::size_t keptEnded_ = kKeptEnded;
  std::deque<Task> tasks_;  // by ID
  TaskId nextId_ = 1;
};

}  // namespace rgnav
