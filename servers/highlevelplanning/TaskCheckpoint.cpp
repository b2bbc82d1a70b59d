// The High-Level Planning module's checkpoint (see TaskCheckpoint.h).
#include "servers/highlevelplanning/TaskCheckpoint.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/common/JsonForms.h"
#include "servers/pathplanning/PlanStore.h"

namespace rgnav {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "rgnav-tasks";
constexpr int kVersion = 1;

template <class Enum>
Enum enumFrom(const json& j, Enum last, const char* what) {
  const long long value = integerFrom(j);
  if (value < 0 || value > static_cast<long long>(last))
    throw FormatError("<checkpoint>", 0, std::string("unknown ") + what + " " + std::to_string(value));
  return static_cast<Enum>(value);
}

RegionId regionFrom(const json& j) {
  const RegionId region = integerFrom(j);
  return region;
}

json taskJson(const Task& t) {
  return {{"id", t.id},
          {"request", t.request},
          {"kind", static_cast<int>(t.kind)},
          {"goal", planGoalJson(t.goal)},
          {"state", static_cast<int>(t.state)},
          {"reason", t.reason},
          {"progress", t.progress},
          {"drive", t.drive},
          {"drives", t.drives},
          {"distanceLeft", jsonNumber(t.distanceLeftM)}};
}

Task taskFrom(const json& j) {
  Task t;
  t.id = integerFrom(j.at("id"));
  t.request = integerFrom(j.at("request"));
  t.kind = enumFrom(j.at("kind"), TaskKind::Stop, "task kind");
  t.goal = planGoalFrom(j.at("goal"));
  t.state = enumFrom(j.at("state"), TaskState::Done, "task state");
  t.reason = j.at("reason").get<std::string>();
  t.progress = j.at("progress").get<std::string>();
  t.drive = integerFrom(j.at("drive"));
  t.drives = static_cast<std::uint32_t>(integerFrom(j.at("drives")));
  t.distanceLeftM = numberFrom(j.at("distanceLeft"));
  return t;
}

}  // namespace

const std::uint64_t* AnsweredRequests::find(std::uint64_t request) const {
  auto it = std::find_if(answers.begin(), answers.end(), [&](const auto& a) { return a.first == request; });
  return it == answers.end() ? nullptr : &it->second;
}

void AnsweredRequests::add(std::uint64_t request, std::uint64_t answer) {
  answers.emplace_back(request, answer);
  while (answers.size() > kKept) answers.pop_front();
}

std::string serializeTasks(const HighLevelPlanningState& state) {
  json tasks = json::array();
  for (const Task& t : state.queue.tasks()) tasks.push_back(taskJson(t));
  json questions = json::array();
  for (const NamingQuestion& q : state.dialog.waiting())
    questions.push_back({{"id", q.id}, {"region", q.region}, {"where", jsonPoint(q.where)}, {"text", q.text}});
  json asked = json::array();
  for (RegionId r : state.dialog.asked()) asked.push_back(r);
  json requests = json::array();
  for (const auto& [request, answer] : state.requests.answers) requests.push_back({request, answer});
  return json{{"format", kFormat},
              {"version", kVersion},
              {"nextTask", state.queue.nextId()},
              {"tasks", tasks},
              {"nextQuestion", state.dialog.nextId()},
              {"questions", questions},
              {"asked", asked},
              {"requests", requests}}
             .dump() +
         "\n";
}

HighLevelPlanningState deserializeTasks(const std::string& text, const std::string& source) {
  return readingJson(source, [&] {
    const json j = json::parse(text);
    if (j.at("format") != kFormat || j.at("version") != kVersion)
      throw FormatError(source, 0, std::string("not a ") + kFormat + " version " + std::to_string(kVersion) + " file");
    std::vector<Task> tasks;
    for (const json& t : j.at("tasks")) tasks.push_back(taskFrom(t));
    std::vector<NamingQuestion> questions;
    for (const json& q : j.at("questions"))
      questions.push_back({static_cast<QuestionId>(integerFrom(q.at("id"))), regionFrom(q.at("region")),
                           pointFrom(q.at("where")), q.at("text").get<std::string>()});
    std::set<RegionId> asked;
    for (const json& r : j.at("asked")) asked.insert(regionFrom(r));
    AnsweredRequests requests;
    for (const json& r : j.at("requests")) requests.add(integerFrom(r.at(0)), integerFrom(r.at(1)));
    // A queue out of order is an InvalidArgumentError, which readingJson reports as the file's.
    return HighLevelPlanningState{TaskQueue(std::move(tasks), integerFrom(j.at("nextTask"))),
                                  NamingDialog(std::move(questions), std::move(asked), integerFrom(j.at("nextQuestion"))),
                                  std::move(requests)};
  });
}

}  // namespace rgnav
