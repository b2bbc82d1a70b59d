// HighLevelPlanningClient calls through the retrying connection (see HighLevelPlanningClient.h).
#include "clientlibs/highlevelplanning/HighLevelPlanningClient.h"

#include "clientlibs/common/convert.h"
#include "clientlibs/highlevelplanning/convert.h"
#include "clientlibs/pathplanning/convert.h"

namespace rgnav {

using Planning = RGNav::HighLevelPlanning_ptr;

namespace {

Task taskOf(RGNav::TaskInfo* info) {
  RGNav::TaskInfo_var held = info;
  return fromIdl(held.in());
}

}  // namespace

HighLevelPlanningClient::HighLevelPlanningClient(ClientSettings settings, std::string objectName)
    : ModuleClientOf(std::move(objectName), std::move(settings)) {}

Task HighLevelPlanningClient::goTo(const PlanGoal& goal, std::uint64_t request) {
  const std::uint64_t id = requestIds_(request);
  const RGNav::PlanGoal wire = toIdl(goal);
  return connection_.call("goTo", [&](Planning p) { return taskOf(p->goTo(id, wire)); });
}

Task HighLevelPlanningClient::explore(std::uint64_t request) {
  const std::uint64_t id = requestIds_(request);
  return connection_.call("explore", [&](Planning p) { return taskOf(p->explore(id)); });
}

Task HighLevelPlanningClient::stop(std::uint64_t request) {
  const std::uint64_t id = requestIds_(request);
  return connection_.call("stop", [&](Planning p) { return taskOf(p->stop(id)); });
}

Task HighLevelPlanningClient::cancel(TaskId task, std::uint64_t request) {
  const std::uint64_t id = requestIds_(request);
  return connection_.call("cancel", [&](Planning p) { return taskOf(p->cancel(id, task)); });
}

Task HighLevelPlanningClient::task(TaskId id) {
  return connection_.call("task", [&](Planning p) { return taskOf(p->task(id)); });
}

std::vector<Task> HighLevelPlanningClient::tasks() {
  return connection_.call("tasks", [](Planning p) {
    RGNav::TaskInfoSeq_var seq = p->tasks();
    return fromIdlSeq<std::vector<Task>>(seq.in(), [](const RGNav::TaskInfo& t) { return fromIdl(t); });
  });
}

std::vector<NamingQuestion> HighLevelPlanningClient::questions() {
  return connection_.call("questions", [](Planning p) {
    RGNav::NamingQuestionSeq_var seq = p->questions();
    return fromIdlSeq<std::vector<NamingQuestion>>(seq.in(),
                                                   [](const RGNav::NamingQuestion& q) { return fromIdl(q); });
  });
}

void HighLevelPlanningClient::answer(QuestionId question, const std::string& name, std::uint64_t request) {
  const std::uint64_t id = requestIds_(request);
  connection_.call("answer", [&](Planning p) { p->answer(id, question, name.c_str()); });
}

}  // namespace rgnav
