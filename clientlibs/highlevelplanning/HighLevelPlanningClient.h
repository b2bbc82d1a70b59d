// HighLevelPlanningClient: tasks and the naming dialog of the High-Level Planning module
// (idl/HighLevelPlanning.idl): queue a drive to a goal (a point, a region or an object by name),
// an exploration, a stop; cancel a task; the tasks by ID with their state and progress; the naming
// questions waiting and their answers. goTo, explore, stop, cancel and answer are not idempotent:
// each call carries a random request ID, kept over its retries, so that a retry after a lost
// answer (the module killed meanwhile) gets the answer the module gave it instead of a second
// task. Calls are retried as every client's (ClientConnection.h). Errors: BadArgumentError naming
// the field, NotAvailableError (no such task or question), ModuleFailedError,
// ModuleUnavailableError.
#pragma once

#include <string>
#include <vector>

#include "HighLevelPlanning.hh"
#include "clientlibs/common/ModuleClient.h"
#include "clientlibs/common/RequestIds.h"
#include "core/nav/tasks/NamingQuestion.h"
#include "core/nav/tasks/Task.h"

namespace rgnav {

class HighLevelPlanningClient : public ModuleClientOf<RGNav::HighLevelPlanning> {
 public:
  explicit HighLevelPlanningClient(ClientSettings settings = ClientSettings::fromEnvironment(),
                                   std::string objectName = "HighLevelPlanning");

  // `request` 0 makes a new request ID (the answer's Task::request tells it).
  Task goTo(const PlanGoal& goal, std::uint64_t request = 0);
  Task explore(std::uint64_t request = 0);
  // Cancels every task and stops the robot; the stop task (Done).
  Task stop(std::uint64_t request = 0);
  // `id` 0: the active task.
  Task cancel(TaskId id = 0, std::uint64_t request = 0);
  Task task(TaskId id);
  std::vector<Task> tasks();
  std::vector<NamingQuestion> questions();
  void answer(QuestionId question, const std::string& name, std::uint64_t request = 0);

 private:
  RequestIds requestIds_;
};

}  // namespace rgnav
