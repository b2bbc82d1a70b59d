// rgnav-nav: tells the robot of a running set what to do, through its High-Level Planning module
// (idl/HighLevelPlanning.idl), and answers the naming dialog's questions (thesis 6.1.3).
//   rgnav-nav [--naming H:P] [--robot NAME] <command> [--wait]
//   explore                  queue an exploration (thesis chapter 7)
//   go <name>                queue a drive to the region of this name
//   go --object <name>       ... to the object of this name
//   go <x> <y>               ... to this point of the map frame (m; two numbers: a point)
//   tasks                    the tasks the module keeps, with their states
//   questions                the naming questions waiting for an answer
//   answer <question> <name> name the question's region
//   cancel [<task>]          cancel a task (default: the active one)
//   stop                     cancel every task and stop the robot
// A queued task prints "task <id> queued: <what>"; with --wait the tool follows it, prints its
// progress when it changes and its outcome ("task <id> reached", "... blocked: <why>"). Exit 0;
// with --wait, 3 when the task ended blocked, 4 when it was cancelled; 2 on any error (a module
// that does not answer is reported with what to do).
#include <cstdio>
#include <iostream>
#include <thread>
#include <vector>

#include "clientlibs/highlevelplanning/HighLevelPlanningClient.h"
#include "tools/common/StrictArguments.h"
#include "tools/common/ToolClient.h"

using namespace rgnav;

namespace {

constexpr int kBlocked = 3;
constexpr int kCancelled = 4;

const char* kUsage =
    "rgnav-nav [--naming host:port] [--robot NAME] <command> [--wait]\n"
    "  explore | go <region name> | go --object <name> | go <x> <y> | tasks | questions |\n"
    "  answer <question id> <name> | cancel [<task id>] | stop\n"
    "  --naming: the set's naming service (default: RGNAV_NAMING); --robot (default: RGNAV_ROBOT or tumbot);\n"
    "  --wait: follow the queued task to its end\n";

struct Arguments {
  std::string naming, robot;
  bool object = false, wait = false, help = false;
  std::vector<std::string> words;  // the command and its arguments
};

Arguments parse(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&] {
      if (i + 1 >= argc) throw ArgumentError(arg, "", "needs a value");
      return std::string(argv[++i]);
    };
    if (arg == "--naming") a.naming = value();
    else if (arg == "--robot") a.robot = value();
    else if (arg == "--object") a.object = true;
    else if (arg == "--wait") a.wait = true;
    else if (arg == "--help" || arg == "-h") a.help = true;
    else if (arg.rfind("--", 0) == 0) throw ArgumentError(arg, arg, "is no option of rgnav-nav");
    else a.words.push_back(arg);
  }
  return a;
}

std::string what(const Task& t) { return t.kind == TaskKind::GoTo ? "goTo " + describeGoal(t.goal) : toString(t.kind); }

void printTask(const Task& t) {
  std::printf("task %llu %s: %s", static_cast<unsigned long long>(t.id), what(t).c_str(), toString(t.state).c_str());
  if (!t.reason.empty()) std::printf(": %s", t.reason.c_str());
  if (t.state == TaskState::Active)
    std::printf(" (%s; drives=%u left=%.1f m)", t.progress.c_str(), t.drives, t.distanceLeftM);
  std::printf("\n");
}

void expectWords(const Arguments& a, std::size_t low, std::size_t high) {
  if (a.words.size() < low || a.words.size() > high)
    throw ArgumentError(a.words.front(), "", "takes " + std::to_string(low - 1) +
                                                 (high > low ? " to " + std::to_string(high - 1) : "") + " arguments");
}

PlanGoal goalOf(const Arguments& a) {
  expectWords(a, 2, 3);
  if (a.words.size() == 3) {
    if (a.object) throw ArgumentError("--object", "", "takes one name, not x y");
    return PlanGoal::at({parseFiniteNumber(a.words[1], "x"), parseFiniteNumber(a.words[2], "y")});
  }
  return a.object ? PlanGoal::atObject(a.words[1]) : PlanGoal::inRegionNamed(a.words[1]);
}

// Follows the task until it ends; the exit code for its outcome.
int follow(HighLevelPlanningClient& planning, TaskId id) {
  std::string shown;
  for (;;) {
    const Task t = planning.task(id);
    if (ended(t.state)) {
      printTask(t);
      if (t.state == TaskState::Blocked) return kBlocked;
      return t.state == TaskState::Cancelled ? kCancelled : 0;
    }
    const std::string now = toString(t.state) + " " + t.progress;
    if (now != shown) printTask(t);
    shown = now;
    std::fflush(stdout);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
}

int queued(HighLevelPlanningClient& planning, const Task& t, bool wait) {
  std::printf("task %llu queued: %s\n", static_cast<unsigned long long>(t.id), what(t).c_str());
  std::fflush(stdout);
  return wait ? follow(planning, t.id) : 0;
}

int run(const Arguments& a) {
  const std::string& command = a.words.front();
  if (command != "go" && a.object) throw ArgumentError("--object", "", "goes with go");
  if (command == "go") {
    const PlanGoal goal = goalOf(a);
    HighLevelPlanningClient planning(toolClientSettings(a.naming, a.robot));
    return queued(planning, planning.goTo(goal), a.wait);
  }
  if (command == "explore") {
    expectWords(a, 1, 1);
    HighLevelPlanningClient planning(toolClientSettings(a.naming, a.robot));
    return queued(planning, planning.explore(), a.wait);
  }
  if (command == "answer") {
    expectWords(a, 3, 3);
    const QuestionId question = parseId(a.words[1], "question id");
    HighLevelPlanningClient planning(toolClientSettings(a.naming, a.robot));
    planning.answer(question, a.words[2]);
    std::printf("question %llu answered: %s\n", static_cast<unsigned long long>(question), a.words[2].c_str());
    return 0;
  }
  if (command == "cancel") {
    expectWords(a, 1, 2);
    const TaskId id = a.words.size() == 2 ? parseId(a.words[1], "task id") : 0;
    HighLevelPlanningClient planning(toolClientSettings(a.naming, a.robot));
    printTask(planning.cancel(id));
    return 0;
  }
  expectWords(a, 1, 1);
  HighLevelPlanningClient planning(toolClientSettings(a.naming, a.robot));
  if (command == "stop") {
    printTask(planning.stop());
  } else if (command == "tasks") {
    for (const Task& t : planning.tasks()) printTask(t);
  } else if (command == "questions") {
    for (const NamingQuestion& q : planning.questions())
      std::printf("question %llu: region %llu at %.2f %.2f: %s\n", static_cast<unsigned long long>(q.id),
                  static_cast<unsigned long long>(q.region.value()), q.where.x(), q.where.y(), q.text.c_str());
  } else {
    throw ArgumentError("command", command, "is no command of rgnav-nav");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Arguments a = parse(argc, argv);
    if (a.help) {
      std::cout << kUsage;
      return 0;
    }
    if (a.words.empty()) throw ArgumentError("command", "", "is missing");
    return run(a);
  } catch (const ModuleUnavailableError& e) {
    reportUnreachable("rgnav-nav", e, true);
  } catch (const ArgumentError& e) {
    std::cerr << "rgnav-nav: " << e.what() << "\n" << kUsage;
  } catch (const std::exception& e) {
    std::cerr << "rgnav-nav: " << e.what() << std::endl;
  }
  return 2;
}
